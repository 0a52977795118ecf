// libFuzzer entry point: the PLY mesh reader and hrsr check's measures (see fuzz_targets.h).
#include "fuzz_targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    hrsr::fuzz::check_mesh_bytes(data, size);
    return 0;
}
