#pragma once
// The dialect records' texts people read (setting labels, groups, units, option names, help;
// action labels and effects; preset names and descriptions) translated where they are shown.
// They are marked for translation in translations/schema_texts.cpp, the catalog written from the
// records (translations/catalog), in one context per dialect: "Schema/nvs".
#include <QByteArray>
#include <QString>

#include <string_view>

namespace gnss::config {

class SchemaTexts {
public:
    SchemaTexts() = default; // no dialect: texts stay as written
    explicit SchemaTexts(std::string_view dialectId);
    // The translation of `text` for the current language; `text` itself when there is none.
    QString operator()(std::string_view text) const;
    // "Schema/nvs": the translation context of the dialect's texts.
    static QByteArray context(std::string_view dialectId);

private:
    QByteArray context_;
};

} // namespace gnss::config
