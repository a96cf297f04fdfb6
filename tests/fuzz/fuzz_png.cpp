// libFuzzer target (docs/reliability.md, "Fuzz targets"): a PNG loaded as
// Image2D through the Loader.
// The rules are m3gfuzz::checkPng in FuzzChecks.h; scripts/fuzz runs it.
#include "FuzzMain.h"

M3G_FUZZ_TARGET(m3gfuzz::checkPng)
