// libFuzzer target (docs/reliability.md, "Fuzz targets"): a JPEG loaded as
// Image2D through the Loader (libjpeg-turbo behind scene/io/JpegImage.cpp).
// The rules are m3gfuzz::checkJpeg in FuzzChecks.h; scripts/fuzz runs it.
#include "FuzzMain.h"

M3G_FUZZ_TARGET(m3gfuzz::checkJpeg)
