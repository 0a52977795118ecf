// Points that D-32 takes out of folds (docs/ALGORITHM.md D-32) are reported apart from r_v: the
// tests of r_v count them as kept and bound their share on its own, so that a loss before D-32
// and a growing D-32 share both fail (docs/STATUS.md, known gap 14).
#pragma once

#include "reconstruction.h"

#include <gtest/gtest.h>

#include <string>

namespace hrsr::testing {

/// The most of the input that D-32 may drop on the models and surfaces the tests use (when this
/// was written: the feline with HRsR at p = 0.25 0.27 %, the camel head with RsR 0.18 %).
inline constexpr double kMaxFoldShare = 0.003;

/// r_v, with the points dropped in folds counted as kept, at least `at_least`; their own share
/// at most kMaxFoldShare.
inline void expect_r_v(const ReconstructionReport& r, double at_least,
                       const std::string& context = "") {
    const double n = double(r.preprocess.input_points);
    const double folds = double(r.dropped_fold.size());
    EXPECT_GE((double(r.referenced_input_points) + folds) / n, at_least) << context;
    EXPECT_LE(folds / n, kMaxFoldShare) << context << ": points dropped in folds (D-32)";
}

} // namespace hrsr::testing
