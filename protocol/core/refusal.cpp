#include "core/refusal.h"

namespace gnss {

Refusal refusal(const char *form, std::vector<std::string> args) {
    Refusal r;
    r.form = form;
    // %1 ... %9 replaced by their arguments, as QString::arg would (the GUI's translation).
    for (const char *p = form; *p; ++p) {
        if (p[0] == '%' && p[1] >= '1' && p[1] <= '9' && std::size_t(p[1] - '1') < args.size()) {
            r.text += args[std::size_t(p[1] - '1')];
            ++p;
        } else {
            r.text += *p;
        }
    }
    r.args = std::move(args);
    return r;
}

} // namespace gnss
