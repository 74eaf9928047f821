#pragma once
// What a receiver's settings are, in words: every setting the engine knows a value of (read
// back, or written when write-only), in schema order, as "label (unit)" → value (an option's
// label when the value is one of the setting's options), translated. The qualification report
// records it beside the campaign.
#include <QString>

#include <utility>
#include <vector>

namespace gnss::config {

class SettingsEngine;

std::vector<std::pair<QString, QString>> settingsSnapshot(const SettingsEngine &engine);

} // namespace gnss::config
