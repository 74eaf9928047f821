// GeoStar messages → the vendor-neutral receiver state: identity from RQUERY (the module named by
// configuration register 2), the status word and registers as reports, the jamming flag.
#include "geostar/geostar_state.h"
#include "geostar/geostar_messages.h"
#include "state/receiver_state.h"
#include "state/report_json.h"

namespace gnss::geostar {

bool updateState(const Message &m, ReceiverState &st) {
    if (const auto *r = message_cast<Rquery>(m)) {
        st.identity.vendor = "GeoStar";
        const auto type = r->config2.receiverType();
        st.identity.model = std::string(type.empty() ? r->receiverName : type);
        st.identity.firmware =
                std::string(r->firmwareVersion.empty() ? r->firmware : r->firmwareVersion);
        st.reports["Status and configuration (RQUERY)"] = messageJson(m);
        st.jamming = r->status.jammingDetected;
        return true;
    }
    if (message_cast<Nquery>(m)) {
        st.reports["Output settings (NQUERY)"] = messageJson(m);
        return true;
    }
    return false;
}

} // namespace gnss::geostar
