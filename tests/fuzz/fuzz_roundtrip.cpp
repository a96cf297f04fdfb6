// libFuzzer target (issue 8, "Fuzzing"): the writer round trip, load -> save -> load.
// The rules are m3gfuzz::checkRoundTrip in FuzzChecks.h; scripts/fuzz runs it.
#include "FuzzMain.h"

M3G_FUZZ_TARGET(m3gfuzz::checkRoundTrip)
