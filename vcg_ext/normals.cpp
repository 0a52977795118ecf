#include "normals.h"

#include "preprocess/preprocess.h"

#include <utility>

namespace hrsr {

OrientedPoints estimate_normals(const PointSet& input, const PreprocessOptions& options,
                                const Execution& exec, PreprocessReport& report) {
    PreparedCloud cloud = preprocess(input, options, exec, report);
    return {raw(cloud.input_index.values()), std::move(cloud.normals)};
}

} // namespace hrsr
