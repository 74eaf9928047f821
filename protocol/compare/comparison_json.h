#pragma once
// A comparison as gnss-cli compare prints it: a JSON line per matched epoch, the report as one
// JSON object, and the report in words.
#include "compare/comparison.h"

#include <string>

namespace gnss {
class JsonWriter;
}

namespace gnss::compare {

// {"time":"10:00:01.000","fix":["rtk_fixed","3d"],"differences":[{"receiver":..,"east":..,
// "north":..,"up":..,"horizontal":..,"cn0":[{"sat":"G05","signal":1,"reference":45,"other":42}],
// "only_in_reference":["G07"],"only_in_this":[]}]}
void writeMatchJson(JsonWriter &w, const Match &m, const std::vector<std::string> &names);
// {"receivers":[{"name","dialect","epochs","fix":{"3d":0.9,..}, and after the first
// "difference_m":{"east":{"mean","median","p95"},..,"horizontal":{..},"cep50","cep95"},
// "cn0_db":{"mean","median","p95","signals","per_constellation":{"GPS":{"mean","p95",
// "satellites"}}},"only_in":{"reference":[{"sat","epochs"}],"this":[..]}}],"matched_epochs":N}
void writeReportJson(JsonWriter &w, const Report &r);
// The report in a few lines of words, for people.
std::string reportText(const Report &r);

} // namespace gnss::compare
