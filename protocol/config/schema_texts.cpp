#include "config/schema_texts.h"

#include <QCoreApplication>

namespace gnss::config {

SchemaTexts::SchemaTexts(std::string_view dialectId) : context_(context(dialectId)) {}

QByteArray SchemaTexts::context(std::string_view dialectId) {
    return "Schema/" + QByteArray(dialectId.data(), qsizetype(dialectId.size()));
}

QString SchemaTexts::operator()(std::string_view text) const {
    if (text.empty()) return {};
    const QByteArray source(text.data(), qsizetype(text.size()));
    if (context_.isEmpty()) return QString::fromUtf8(source);
    return QCoreApplication::translate(context_.constData(), source.constData());
}

} // namespace gnss::config
