// Helpers shared by the NVS decoders.
#include "core/field_parse.h"
#include "nvs/nvs_messages.h"

namespace gnss::nvs {

void writeValue(JsonWriter &w, std::string_view text) {
    std::int64_t i;
    double d;
    if (text.empty())
        w.null();
    else if (parseInt(text, i))
        w.value(i);
    else if (parseReal(text, d))
        w.value(d);
    else
        w.value(text);
}

} // namespace gnss::nvs
