// libFuzzer target (docs/reliability.md, "Fuzz targets"): Loader::load(bytes) on .m3g bytes.
// The rules are m3gfuzz::checkLoader in FuzzChecks.h; scripts/fuzz runs it.
#include "FuzzMain.h"

M3G_FUZZ_TARGET(m3gfuzz::checkLoader)
