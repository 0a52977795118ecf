// The cost of the fold phases (issue 16 item 4) without the noise of a whole run: reconstructs a
// cloud once with the fold repair off, then times the search for intersecting pairs (one
// thread), D-26's flips and D-32's removal on that mesh REPEATS times, and prints the median of
// each beside the median of a whole default run at one thread (which includes them). The mesh
// timed alone is numbered as reconstruct() returns it (input order), not in the spatial order
// the run's own fold phases see (D-40). Not part of the hrsr CLI.
//   fold_phase_times CLOUD [REPEATS=5] [hrsr|rsr]
// Exit codes: 0 success, 1 bad input, 2 usage.
#include "io/point_set_reader.h"
#include "mesh/fold_removal.h"
#include "mesh/fold_repair.h"
#include "mesh/fold_search.h"
#include "reconstruction.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

// The coordinates as the writers store them (reconstruction.cpp's written_positions).
std::vector<hrsr::Vec3> written_positions(const hrsr::PointSet& cloud,
                                          const hrsr::Reconstruction& r) {
    std::vector<hrsr::Vec3> written;
    for (std::uint32_t i : r.vertex_input_index) {
        hrsr::Vec3 p = cloud.positions[i];
        if (cloud.precision == hrsr::CoordinatePrecision::Float)
            for (int k = 0; k < 3; ++k) p[k] = double(float(p[k]));
        written.push_back(p);
    }
    return written;
}

} // namespace

int main(int argc, char** argv) {
    const int repeats = argc >= 3 ? std::atoi(argv[2]) : 5;
    const bool rsr = argc == 4 && std::string(argv[3]) == "rsr";
    if (argc < 2 || argc > 4 || repeats < 1 ||
        (argc == 4 && !rsr && std::string(argv[3]) != "hrsr")) {
        std::fprintf(stderr, "usage: fold_phase_times CLOUD [REPEATS=5] [hrsr|rsr]\n");
        return 2;
    }
    try {
        const hrsr::PointSet cloud = hrsr::io::read_point_set(argv[1]);
        hrsr::ReconstructionOptions options;
        if (rsr) options.method = hrsr::Method::Rsr;
        hrsr::Execution one_thread;
        one_thread.threads = 1;
        std::vector<double> whole, search_s, repair_s, removal_s;
        for (int r = 0; r < repeats; ++r) {
            hrsr::ReconstructionReport report;
            const Clock::time_point start = Clock::now();
            hrsr::reconstruct(cloud, options, one_thread, report);
            whole.push_back(seconds_since(start));
        }
        options.rsr.fold_repair_rounds = 0;
        hrsr::ReconstructionReport unrepaired_report;
        const hrsr::Reconstruction unrepaired =
            hrsr::reconstruct(cloud, options, one_thread, unrepaired_report);
        const std::vector<hrsr::Vec3> written = written_positions(cloud, unrepaired);
        std::size_t pairs = 0, left = 0;
        for (int r = 0; r < repeats; ++r) {
            std::vector<hrsr::Triangle> triangles = unrepaired.triangles;
            Clock::time_point start = Clock::now();
            hrsr::FoldSearch search(written, triangles, one_thread);
            search_s.push_back(seconds_since(start));
            pairs = search.pairs.size();
            start = Clock::now();
            hrsr::repair_folds(search, triangles, hrsr::RsrOptions{}.fold_repair_rounds);
            repair_s.push_back(seconds_since(start));
            start = Clock::now();
            const hrsr::FoldRemoval removal =
                hrsr::remove_folds(search, unrepaired.vertex_normals, triangles);
            removal_s.push_back(seconds_since(start));
            left = removal.stats.pairs_after;
        }
        const double folds = median(search_s) + median(repair_s) + median(removal_s);
        std::printf("pairs %zu (left %zu); medians of %d, one thread: search %.3f s, flips "
                    "(D-26) %.3f s, removal (D-32) %.3f s; fold phases %.3f s of a whole run's "
                    "%.3f s: %.1f %%\n",
                    pairs, left, repeats, median(search_s), median(repair_s), median(removal_s),
                    folds, median(whole), 100.0 * folds / median(whole));
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fold_phase_times: %s\n", e.what());
        return 1;
    }
}
