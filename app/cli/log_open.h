#pragma once
// What export, summary and play share: the log viewer's engine opened on FILE (with --dialect
// and --lenient), and the epochs between --from and --to.
#include "cli/cli_commands.h"
#include "logview/log_view.h"

#include <memory>

namespace gnss::cli {

struct OpenedLog {
    // FILE "-": standard input, read whole into a temporary file (the engine maps and seeks its
    // log), removed when this goes (declared first: after the view).
    struct TempFile {
        std::string path;
        TempFile() = default;
        TempFile(const TempFile &) = delete;
        TempFile &operator=(const TempFile &) = delete;
        ~TempFile();
    } stdinCopy;
    std::unique_ptr<logview::LogView> view;
    std::string path;
    std::size_t first = 0, last = 0; // epochs [first, last]; last < first: none
    bool empty() const { return last < first; }
};

// Opens the one positional FILE ("-": standard input) and indexes it (progress on standard error
// when it is a terminal). Returns 0 on success, else the exit status (1 unreadable, 2 usage) with
// the message printed. An empty log or one without NMEA opens (its warnings are printed).
int openLogForCommand(const CliContext &ctx, OpenedLog &out);

} // namespace gnss::cli
