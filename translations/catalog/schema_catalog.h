#pragma once
// The texts of the dialects' records that people read (settings labels, groups, units, option
// names, help; actions and presets), written out as a C++ file for lupdate: the schemas are
// Qt-free data, so their texts are marked for translation here, one context per dialect
// ("Schema/nvs"), and translated where they are shown (ui/settings/schema_texts.h).
#include <span>
#include <string>
#include <vector>

namespace gnss {
struct Dialect;

// The whole catalog file, deterministic: the same dialects give the same bytes.
std::string schemaCatalogSource(std::span<const Dialect *const> dialects);

// Every text of one dialect the catalog lists, in first-seen order, without repeats.
std::vector<std::string> schemaTexts(const Dialect &d);

} // namespace gnss
