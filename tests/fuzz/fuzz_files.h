#pragma once
// Files for the harnesses that read from disk (the log viewer maps its log, a recording is two
// files): one scratch folder per process, in memory where the system has /dev/shm, removed at
// exit. Each input overwrites the same few names, so nothing piles up over millions of runs.
#include "fuzz_common.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

namespace gnss::fuzz {

class ScratchDir {
public:
    static const ScratchDir &get() {
        static const ScratchDir d;
        return d;
    }
    // `name` in the folder (not created).
    std::string path(std::string_view name) const { return dir_ + "/" + std::string(name); }

    ScratchDir(const ScratchDir &) = delete;
    ScratchDir &operator=(const ScratchDir &) = delete;
    ~ScratchDir() {
        std::error_code ec;
        std::filesystem::remove_all(dir_, ec);
    }

private:
    ScratchDir() {
        std::error_code ec;
        const char *tmp = std::getenv("TMPDIR");
        std::string base = std::filesystem::is_directory("/dev/shm", ec) ? "/dev/shm"
                           : tmp && *tmp                                 ? tmp
                                                                         : "/tmp";
        std::string templ = base + "/gnss-fuzz-XXXXXX";
        if (!::mkdtemp(templ.data())) fail("cannot make a scratch folder", templ);
        dir_ = templ;
    }
    std::string dir_;
};

// Writes (or with `append`, extends) a file with exactly `bytes`; aborts when it cannot, as
// that is the machine's fault, not the input's.
GNSS_FUZZ_NO_COVERAGE inline void writeFile(const std::string &path, std::string_view bytes,
                                            bool append = false) {
    std::ofstream out(path, std::ios::binary | (append ? std::ios::app : std::ios::trunc));
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) fail("cannot write a scratch file", path);
}

GNSS_FUZZ_NO_COVERAGE inline void removeFile(const std::string &path) {
    std::error_code ec;
    std::filesystem::remove(path, ec);
}

} // namespace gnss::fuzz
