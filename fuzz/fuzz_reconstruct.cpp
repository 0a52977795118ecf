// libFuzzer entry point: reconstruction of small clouds made from the input (see fuzz_targets.h).
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    hrsr::fuzz::reconstruct_bytes(data, size);
    return 0;
}
