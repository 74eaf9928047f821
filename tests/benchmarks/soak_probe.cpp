#include "soak_probe.h"

#include <QFile>

#include <malloc.h>
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>

namespace gnss::soak {
namespace {

// A "kB" field of /proc/PID/status in MB; -1 when there is none.
double statusMb(const QString &statusPath, const QByteArray &field) {
    QFile f(statusPath);
    if (!f.open(QIODevice::ReadOnly)) return -1;
    for (const QByteArray &line : f.readAll().split('\n'))
        if (line.startsWith(field))
            return line.mid(field.size()).trimmed().split(' ').front().toDouble() / 1024.0;
    return -1;
}

} // namespace

ProcessSample sampleSelf() {
    ProcessSample p;
    p.rssMb = statusMb(QStringLiteral("/proc/self/status"), "VmRSS:");
    p.anonMb = statusMb(QStringLiteral("/proc/self/status"), "RssAnon:");
    const struct mallinfo2 m = mallinfo2();
    p.heapMb = double(m.uordblks + m.hblkhd) / (1024.0 * 1024.0);
    p.mmapMb = double(m.hblkhd) / (1024.0 * 1024.0);
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    p.cpuSeconds = double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
                   double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
    return p;
}

ProcessSample samplePid(long long pid) {
    ProcessSample p;
    p.rssMb = statusMb(QStringLiteral("/proc/%1/status").arg(pid), "VmRSS:");
    p.anonMb = statusMb(QStringLiteral("/proc/%1/status").arg(pid), "RssAnon:");
    QFile f(QStringLiteral("/proc/%1/stat").arg(pid));
    if (f.open(QIODevice::ReadOnly)) {
        const QByteArray stat = f.readAll();
        // Fields after the command name (which may hold spaces): state is field 3; utime and
        // stime are fields 14 and 15.
        const QList<QByteArray> fields = stat.mid(stat.lastIndexOf(')') + 2).split(' ');
        if (fields.size() > 12)
            p.cpuSeconds = double(fields[11].toLongLong() + fields[12].toLongLong()) /
                           double(sysconf(_SC_CLK_TCK));
    }
    return p;
}

void SoakTable::header(const std::vector<ListSize> &lists) {
    std::printf("%8s %8s %8s %8s %8s %8s %8s", "sim_h", "real_s", "rss_MB", "anon_MB", "heap_MB",
                "mmap_MB", "cpu_s");
    for (const ListSize &l : lists) std::printf(" %s", qPrintable(l.name));
    std::printf("\n");
    std::fflush(stdout);
}

void SoakTable::row(double simHours, double realSeconds, const ProcessSample &p,
                    const std::vector<ListSize> &lists) {
    std::printf("%8.2f %8.1f %8.1f %8.1f %8.1f %8.1f %8.1f", simHours, realSeconds, p.rssMb,
                p.anonMb, p.heapMb, p.mmapMb, p.cpuSeconds);
    for (const ListSize &l : lists) std::printf(" %lld", l.size);
    std::printf("\n");
    std::fflush(stdout);
    if (largest_.size() != lists.size()) largest_ = lists;
    for (std::size_t i = 0; i < lists.size(); ++i) {
        largest_[i].size = std::max(largest_[i].size, lists[i].size);
        largest_[i].cap = lists[i].cap;
    }
}

bool SoakTable::verdict(const ProcessSample &last, double limitMb) {
    bool ok = true;
    if (warmSet_) {
        const double rss = last.rssMb - warm_.rssMb;
        const bool rssOk = rss < limitMb;
        std::printf("RSS growth after warm-up: %+.1f MB (%.1f -> %.1f), limit %.0f MB: %s\n", rss,
                    warm_.rssMb, last.rssMb, limitMb, rssOk ? "PASS" : "FAIL");
        ok = ok && rssOk;
        std::printf("  of which anonymous (RssAnon, not libraries' pages): %+.1f MB (%.1f -> "
                    "%.1f)\n",
                    last.anonMb - warm_.anonMb, warm_.anonMb, last.anonMb);
        if (last.heapMb >= 0 && warm_.heapMb >= 0) {
            const double heap = last.heapMb - warm_.heapMb;
            const bool heapOk = heap < limitMb;
            std::printf("heap growth after warm-up: %+.1f MB (%.1f -> %.1f), limit %.0f MB: %s\n",
                        heap, warm_.heapMb, last.heapMb, limitMb, heapOk ? "PASS" : "FAIL");
            ok = ok && heapOk;
        }
    } else {
        std::printf("no sample after the warm-up: growth not measured: FAIL\n");
        ok = false;
    }
    for (const ListSize &l : largest_) {
        const bool listOk = l.cap < 0 || l.size <= l.cap;
        if (l.cap < 0)
            std::printf("  %-28s largest %lld (no cap named)\n", qPrintable(l.name), l.size);
        else
            std::printf("  %-28s largest %lld, cap %lld: %s\n", qPrintable(l.name), l.size, l.cap,
                        listOk ? "PASS" : "FAIL");
        ok = ok && listOk;
    }
    std::printf("%s\n", ok ? "PASS" : "FAIL");
    std::fflush(stdout);
    return ok;
}

} // namespace gnss::soak
