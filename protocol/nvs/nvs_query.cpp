// 3.8 Q: query for one standard or proprietary sentence. Decoded by the standard table (the
// registry's query rule); NVS only adds the encoder.
//
//   $ccGPQ,c-c*hh      $GPGPQ,PNVGTST*21
//    cc requester talker (any), GP the receiver's talker (always GP), c-c the address wanted:
//    3 characters for standard sentences, all 7 for proprietary ones
#include "nvs/nvs_encode_util.h"

namespace gnss::nvs {

namespace {
bool upperAlnum(std::string_view s) {
    for (char c : s)
        if (!((c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9'))) return false;
    return !s.empty();
}
} // namespace

EncodeResult encodeQuery(std::string_view requesterTalker, std::string_view address) {
    if (requesterTalker.size() != 2 || !upperAlnum(requesterTalker))
        return refuse("Q requester talker: '" + std::string(requesterTalker) +
                      "' must be two upper-case letters or digits (GP)");
    if (!(address.size() == 3 || (address.size() == 7 && address.front() == 'P')) ||
        !upperAlnum(address))
        return refuse("Q address: '" + std::string(address) +
                      "' must be 3 characters (GGA) or a 7-character proprietary address "
                      "(PNVGTST)");
    return built(std::string(requesterTalker) + "GPQ," + std::string(address));
}

} // namespace gnss::nvs
