// Nemerix messages → the vendor-neutral receiver state: version reports and the settings report
// (PNMRX603) shown as status reports.
#include "nemerix/nemerix_state.h"
#include "nemerix/nemerix_messages.h"
#include "state/receiver_state.h"
#include "state/report_json.h"

namespace gnss::nemerix {

bool updateState(const Message &m, ReceiverState &st) {
    if (m.type == &VersionReport::kSoftwareType) {
        const auto &v = static_cast<const VersionReport &>(m);
        st.identity.vendor = "Nemerix";
        // The spec gives no layout: a first field that names the module ("VT002") is the model,
        // the rest is the firmware; otherwise all of it is the firmware.
        std::size_t first = 0;
        if (v.count >= 2 && !v.fieldsText[0].empty() &&
            v.fieldsText[0].find(' ') == std::string_view::npos && v.fieldsText[0].size() <= 12) {
            st.identity.model = std::string(v.fieldsText[0]);
            first = 1;
        } else if (st.identity.model.empty()) {
            st.identity.model = "receiver";
        }
        std::string fw;
        for (std::size_t i = first; i < v.count; ++i) {
            if (!fw.empty()) fw += ' ';
            fw += v.fieldsText[i];
        }
        st.identity.firmware = fw;
        st.reports["Software version (PNMRX600)"] = messageJson(m);
        return true;
    }
    if (m.type == &VersionReport::kFlashType) {
        st.reports["Flash content (PNMRX602)"] = messageJson(m);
        return true;
    }
    if (const auto *r = message_cast<SettingsReport>(m)) {
        st.reports["Settings report (PNMRX603) " + std::to_string(r->number)] = messageJson(m);
        return true;
    }
    return false;
}

} // namespace gnss::nemerix
