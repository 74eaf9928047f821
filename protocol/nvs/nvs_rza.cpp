// 4.4 PNVGRZA: COM port protocol and baud rate (command and reply; the receiver answers with the
// new settings and switches within 100 ms).
//
//   $PNVGRZA,x,x,x*hh      $PNVGRZA,1,115200,1*6D
//            0 port (0 current, 1 COM1, 2 COM2, 3 USB), 1 baud (4800-460800),
//            2 protocol (0 disable, 1 NMEA 0183, 7 RTCM)
#include "nvs/nvs_encode_util.h"

#include "core/field_table.h"

namespace gnss::nvs {

const MessageType Rza::kType{"PNVGRZA"};

const FieldRow<Rza> Rza::kFields[] = {
        {&Rza::port, "port", "port"},
        {&Rza::baud, "baud rate", "baud"},
        {&Rza::protocol, "protocol", "protocol"},
};

EncodeResult encodeRza(int port, int baud, int protocol) {
    std::string err = checkRange("PNVGRZA port", port, 0, 3);
    // The COM1 rows carry the spec's ranges (every port has the same ones).
    if (err.empty()) err = checkSetting("port.COM1.baud", std::to_string(baud));
    if (err.empty()) err = checkSetting("port.COM1.protocol", std::to_string(protocol));
    if (!err.empty()) return refuse(err);
    return built("PNVGRZA," + std::to_string(port) + "," + std::to_string(baud) + "," +
                 std::to_string(protocol));
}

} // namespace gnss::nvs
