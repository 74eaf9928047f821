#pragma once
// A recording's file name for what a receiver is called ("NV08C-RTK /dev/ttyUSB0" ->
// "NV08C-RTK_dev_ttyUSB0.nmea"): letters, digits, '.', '-' and '_' kept, each run of anything
// else one '_', unique among `taken` ("-2", "-3", ...), which it joins. What gnss-cli record
// --out and the window's File -> Record with several receivers name their files by.
#include <string>
#include <string_view>
#include <vector>

namespace gnss::link {

std::string recordingFileName(std::string_view name, std::vector<std::string> &taken);

} // namespace gnss::link
