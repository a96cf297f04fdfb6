// Proof that the sanitizer build checks what scripts/test says it checks
// (docs/reliability.md, "Sanitizer stage of scripts/test"): `leak` loses a heap block, which
// LeakSanitizer must report at exit; `overflow` overflows a signed int, at
// which UndefinedBehaviorSanitizer must stop the program; `race` has two
// threads write one int unsynchronised, which ThreadSanitizer must report
// (scripts/tsan). ctest passes each
// case only on the sanitizer's report (tests/CMakeLists.txt), so a run with
// the leak check or UBSan halting switched off fails instead of passing
// silently.
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <thread>

namespace {
void* volatile sink = nullptr;  // volatile: the compiler may not drop the block
volatile int operand = INT_MAX;
int shared = 0;  // written by two threads without synchronisation
}  // namespace

int main(int argc, char** argv) {
    if (argc == 2 && std::strcmp(argv[1], "leak") == 0) {
        sink = std::malloc(64);
        sink = nullptr;  // the only pointer to the block is gone
        std::puts("leaked 64 bytes");
        return 0;
    }
    if (argc == 2 && std::strcmp(argv[1], "overflow") == 0) {
        const int sum = operand + 1;
        std::printf("continued after undefined behaviour (%d)\n", sum);
        return 0;
    }
    if (argc == 2 && std::strcmp(argv[1], "race") == 0) {
        auto write = [] {
            for (int i = 0; i < 1000; ++i) shared = shared + 1;
        };
        std::thread a(write), b(write);
        a.join();
        b.join();
        std::printf("two threads wrote %d\n", shared);
        return 0;
    }
    std::fputs("usage: m3g_sanitizer_probe leak|overflow|race\n", stderr);
    return 2;
}
