#include "config/refusal_text.h"

#include "config/schema_texts.h"

#include <QCoreApplication>

namespace gnss::config {

QString refusalText(const Refusal &r, std::string_view dialectId) {
    if (!r.form) return QString::fromStdString(r.text);
    const SchemaTexts words(dialectId);
    // An argument is a phrase of the core ("not a number") or one of the dialect's words.
    auto word = [&](const std::string &arg) {
        const QString t = QCoreApplication::translate("Refusal", arg.c_str());
        return t != QString::fromStdString(arg) ? t : words(arg);
    };
    QString out = QCoreApplication::translate("Refusal", r.form);
    // %1 ... %9 at once (QString::arg one by one would rescan what an argument brought in).
    QString filled;
    for (qsizetype i = 0; i < out.size(); ++i) {
        const QChar c = out[i];
        if (c == '%' && i + 1 < out.size() && out[i + 1] >= '1' && out[i + 1] <= '9') {
            const auto k = std::size_t(out[i + 1].unicode() - '1');
            if (k < r.args.size()) {
                filled += word(r.args[k]);
                ++i;
                continue;
            }
        }
        filled += c;
    }
    return filled;
}

QString refusalText(std::string_view error, const Refusal *problem) {
    if (problem && problem->form && problem->text == error) return refusalText(*problem);
    const std::string text(error);
    return QCoreApplication::translate("Refusal", text.c_str());
}

QString refusalText(const EncodeResult &r, std::string_view dialectId) {
    if (r.refusal.form && r.refusal.text == r.error) return refusalText(r.refusal, dialectId);
    return QString::fromStdString(r.error);
}

} // namespace gnss::config
