// stb_image for the fuzz targets: the implementation from Debian's stb_image.h (libstb-dev),
// the same source the prebuilt libstb is compiled from, built here with the fuzzer's coverage
// and sanitizers so that the PNG / BMP / GIF decoders are explored and checked too. The fuzz
// targets link this instead of libstb.
#define STB_IMAGE_IMPLEMENTATION
#include <stb_image.h>
