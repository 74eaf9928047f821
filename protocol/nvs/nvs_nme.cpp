// 4.2 PNVGNME: NMEA output resolution and talker compatibility (command and reply; the receiver
// answers with the new settings, then switches).
//
//   $PNVGNME,x,x[,x]*hh
//            0 time decimals (0-6), 1 position decimals (0-9), 2 talker mode (0/1, optional)
#include "nvs/nvs_encode_util.h"

#include "core/field_table.h"

namespace gnss::nvs {

const MessageType Nme::kType{"PNVGNME"};

const FieldRow<Nme> Nme::kFields[] = {
        {&Nme::timeDecimals, "time decimals", "time_decimals"},
        {&Nme::positionDecimals, "position decimals", "position_decimals"},
        {&Nme::talkerMode, "talker mode", "talker_mode"},
};

EncodeResult encodeNme(int timeDecimals, int positionDecimals, std::optional<int> talkerMode) {
    std::string err = checkSetting("nmea.time_decimals", std::to_string(timeDecimals));
    if (err.empty()) err = checkSetting("nmea.position_decimals", std::to_string(positionDecimals));
    if (err.empty() && talkerMode)
        err = checkSetting("nmea.talker_mode", std::to_string(*talkerMode));
    if (!err.empty()) return refuse(err);
    std::string body =
            "PNVGNME," + std::to_string(timeDecimals) + "," + std::to_string(positionDecimals);
    if (talkerMode) body += "," + std::to_string(*talkerMode);
    return built(body);
}

} // namespace gnss::nvs
