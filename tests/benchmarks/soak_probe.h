#pragma once
// What the soak program measures of a process: resident memory (VmRSS of /proc/PID/status, and
// its anonymous part RssAnon: the libraries' code pages fault in as code first runs),
// heap in use (mallinfo2, this process only) and CPU seconds (user + system), and the table it
// prints: one row per sample with the size of every bounded list, then growth and PASS/FAIL.
#include <QString>

#include <cstdio>
#include <vector>

namespace gnss::soak {

struct ProcessSample {
    double rssMb = -1;  // VmRSS
    double anonMb = -1; // RssAnon: VmRSS without the pages of mapped files (libraries' code)
    double heapMb = -1; // mallinfo2().uordblks (+ hblkhd, mmapped blocks); -1 for another process
    // Of the heap, the blocks malloc mapped on their own (hblkhd: single allocations over the
    // mmap threshold, 128 KiB and up): a step here is one big buffer, not many small ones.
    double mmapMb = -1;
    double cpuSeconds = -1;
};

// This process (getrusage, mallinfo2, /proc/self/status).
ProcessSample sampleSelf();
// Another process (/proc/PID/status and /proc/PID/stat); rssMb -1 once it is gone.
ProcessSample samplePid(long long pid);

// One bounded list: its name, size now, largest size seen and its cap (-1: none named).
struct ListSize {
    QString name;
    long long size = 0;
    long long cap = -1;
};

class SoakTable {
public:
    // `lists`: the names, in the order each sample gives them.
    void header(const std::vector<ListSize> &lists);
    void row(double simHours, double realSeconds, const ProcessSample &p,
             const std::vector<ListSize> &lists);
    // Marks the end of the warm-up: growth is measured from the sample taken here.
    void endWarmUp(const ProcessSample &p) {
        warm_ = p;
        warmSet_ = true;
    }
    // Prints growth from the warm-up to `last`, each list against its cap; true when within
    // `limitMb` and every list at or below its cap.
    bool verdict(const ProcessSample &last, double limitMb);

private:
    ProcessSample warm_;
    bool warmSet_ = false;
    std::vector<ListSize> largest_;
};

} // namespace gnss::soak
