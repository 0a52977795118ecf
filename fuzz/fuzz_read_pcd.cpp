// libFuzzer entry point: the PCD reader (see fuzz_targets.h).
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    hrsr::fuzz::read_pcd_bytes(data, size);
    return 0;
}
