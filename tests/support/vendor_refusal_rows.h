#pragma once
// What the vendor suites' refusal tables share (geostar, nemerix, nvs): the encoder of a row that
// breaks one field of a valid message, and the check of a table of refused settings.
#include "core/settings_schema.h"

#include <QString>
#include <QTest>

#include <functional>
#include <type_traits>

namespace gnss::test {

// A row's encoder: `valid` as `change` leaves it, through `encode`.
template <class M, class Encode>
std::function<EncodeResult()> encodedAfter(M valid, Encode encode,
                                           std::type_identity_t<void (*)(M &)> change) {
    return [=] {
        M m = valid;
        change(m);
        return encode(m);
    };
}

// The _data columns of a table of refused settings: key, value, what the refusal must say.
inline void addRefusedSettingColumns() {
    QTest::addColumn<QString>("key");
    QTest::addColumn<QString>("value");
    QTest::addColumn<QString>("mentions");
}

// The current row's setting through `encode` (which sets it beside a valid one): refused as a
// whole, nothing at all built, and the error says the row's `mentions`.
template <class Encode> void checkRefusedSetting(Encode encode) {
    QFETCH(QString, key);
    QFETCH(QString, value);
    QFETCH(QString, mentions);
    const EncodeResult r = encode(KeyValue{key.toStdString(), value.toStdString()});
    QVERIFY(!r.ok());
    QVERIFY(r.sentences.empty());
    QVERIFY2(QString::fromStdString(r.error).contains(mentions), r.error.c_str());
}

} // namespace gnss::test
