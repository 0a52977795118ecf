// libFuzzer entry point: the XYZ reader (see fuzz_targets.h).
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    hrsr::fuzz::read_xyz_bytes(data, size);
    return 0;
}
