#pragma once
// What an RTCM 3 message number means, in a few words, for the corrections monitor:
// 1005 → "base position", 1074 → "GPS MSM4", 1230 → "GLONASS biases". Plain C++.
#include <string>

namespace gnss::corrections {

// The meaning alone ("base position"); "message N" for numbers this table does not know.
std::string rtcmMessageMeaning(unsigned number);
// "1005: base position".
std::string describeRtcmMessage(unsigned number);
// Observation messages (MSM of any system, legacy 1001-1004 and 1009-1012): the ones whose age
// is the age of the corrections.
bool isObservationMessage(unsigned number);

} // namespace gnss::corrections
