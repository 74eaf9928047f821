#include "nemerix/nemerix_fields.h"

#include "core/refusal.h"

#include <string>

namespace gnss::nemerix {

std::size_t usedFields(const FieldReader &r) {
    std::size_t n = r.count();
    while (n > 0 && r.empty(n - 1)) --n;
    return n;
}

std::size_t pairedFields(FieldReader &r, const char *none, const char *unpaired) {
    const std::size_t n = usedFields(r);
    if (n == 0) r.failSentence(std::string(none));
    if (n % 2 != 0) r.failSentence(std::string(unpaired));
    return n;
}

void readTexts(FieldReader &r, std::span<std::string_view> texts, std::size_t &count) {
    for (std::size_t i = 0; i < r.count(); ++i) {
        if (count == texts.size()) {
            r.failSentence(std::string(QT_TRANSLATE_NOOP("Refusal", "too many fields")));
            break;
        }
        texts[count++] = r.text(i);
    }
}

} // namespace gnss::nemerix
