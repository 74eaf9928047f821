// A deliberate fault of each kind the sanitizer stages must catch, one per argument. ctest runs
// it in the asan and tsan builds and expects it to fail: if the flags of a stage ever stop
// instrumenting the code (or a sanitizer stops halting), these tests fail, and so does CI,
// instead of the stage passing while it checks nothing.
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <thread>

namespace {

// Values the optimiser cannot see through.
volatile int gSize = 8;
volatile int gIndex = 8;
volatile int gLarge = std::numeric_limits<int>::max();
int gShared = 0;

int heapOverflow() {
    char *p = static_cast<char *>(std::malloc(static_cast<std::size_t>(gSize)));
    std::memset(p, 0, static_cast<std::size_t>(gSize));
    const int v = p[gIndex]; // one byte past the block
    std::free(p);
    return v;
}

int useAfterFree() {
    int *p = new int[4]{1, 2, 3, 4};
    delete[] p;
    return p[gIndex % 4];
}

int signedOverflow() {
    int v = gLarge;
    return v + 1;
}

int leak() {
    void *volatile p = std::malloc(64);
    p = nullptr;
    return p == nullptr ? 0 : 1;
}

int dataRace() {
    std::thread a([] {
        for (int i = 0; i < 100000; ++i) ++gShared;
    });
    std::thread b([] {
        for (int i = 0; i < 100000; ++i) ++gShared;
    });
    a.join();
    b.join();
    return gShared == 0;
}

} // namespace

int main(int argc, char **argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: sanitizer_canary heap|free|overflow|leak|race\n");
        return 2;
    }
    const char *what = argv[1];
    int r = 0;
    if (!std::strcmp(what, "heap"))
        r = heapOverflow();
    else if (!std::strcmp(what, "free"))
        r = useAfterFree();
    else if (!std::strcmp(what, "overflow"))
        r = signedOverflow();
    else if (!std::strcmp(what, "leak"))
        r = leak();
    else if (!std::strcmp(what, "race"))
        r = dataRace();
    else
        return 2;
    // Reached only when the sanitizer missed the fault: exit 0, which the WILL_FAIL test takes
    // for a failure.
    std::printf("not caught: %s (%d)\n", what, r);
    return 0;
}
