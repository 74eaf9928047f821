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

// A regular file mapped into memory (read-only). data() is empty when the path is not a regular
// file or cannot be mapped; error() then says why (empty for "not a regular file").
class MappedFile {
public:
    explicit MappedFile(const std::string &path);
    ~MappedFile();
    MappedFile(const MappedFile &) = delete;
    MappedFile &operator=(const MappedFile &) = delete;
    bool ok() const { return data_ != nullptr || mappedEmpty_; }
    std::string_view data() const { return {static_cast<const char *>(data_), size_}; }
    const std::string &error() const { return error_; }

private:
    void *data_ = nullptr;
    std::size_t size_ = 0;
    bool mappedEmpty_ = false;
    std::string error_;
};

} // namespace gnss::cli
