// libFuzzer target (docs/reliability.md, "Fuzz targets"): the writer round
// trip, load -> save -> load.
// The rules are m3gfuzz::checkRoundTrip in FuzzChecks.h; scripts/fuzz runs it.
#include "FuzzMain.h"

M3G_FUZZ_TARGET(m3gfuzz::checkRoundTrip)
