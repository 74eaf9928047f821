#pragma once
// Reads a file or standard input in large chunks (the decoder's speed is the point of `stats`).
#include "core/function_ref.h"

#include <string>
#include <string_view>

namespace gnss::cli {

// Calls onChunk for each chunk read from `path` ("-" or empty: standard input). Returns false
// with `error` set when the input cannot be opened or read.
bool readInput(const std::string &path, FunctionRef<void(std::string_view)> onChunk,
               std::string &error);

} // namespace gnss::cli
