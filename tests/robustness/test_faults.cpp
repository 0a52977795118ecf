// Issue 7, item 3: faults. A progress callback that cancels, throws or reports an allocation
// failure in any phase stops the reconstruction at once with that error (no result, no hang);
// the library is then as good as new. Cancellation points come often enough to be prompt.
#include "parallel.h"
#include "robustness.h"
#include "samplers.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <ctime>
#include <map>
#include <new>
#include <set>
#include <stdexcept>
#include <thread>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace hrsr {
namespace {

using testing::attempt;
using testing::Attempt;
using testing::kMethods;
using testing::name;

// With an observer every RsR component runs on the calling thread with its own phases
// (candidate graph, spanning tree, face split, handles, ears); without one, components below
// 20,000 points run in parallel under "small components". Both paths are exercised.
struct RunSetup {
    Method method;
    bool normals;
    bool observed;
    std::string label() const {
        return std::string(name(method)) + (normals ? "" : ", no normals") +
               (observed ? ", observed" : "");
    }
};

std::vector<RunSetup> setups() {
    std::vector<RunSetup> all;
    for (Method m : kMethods)
        for (bool normals : {true, false})
            for (bool observed : {true, false}) all.push_back({m, normals, observed});
    return all;
}

PointSet cloud(const RunSetup& s) {
    const PointSet t = testing::sample_torus(1000);
    return s.normals ? t : testing::without_normals(t);
}

// Calls per phase of a normal run, phases in order of first call.
std::vector<std::pair<std::string, int>> phase_calls(const PointSet& in, const RunSetup& s) {
    std::vector<std::pair<std::string, int>> calls;
    Progress progress([&](const std::string& phase, double) {
        if (calls.empty() || calls.back().first != phase) calls.emplace_back(phase, 0);
        ++calls.back().second;
        return true;
    });
    rsr::Observer observer;
    const Attempt a = attempt(in, s.method, {}, {1, &progress}, s.observed ? &observer : nullptr);
    EXPECT_EQ(a.kind, Attempt::Mesh) << a.message;
    return calls;
}

enum class Fault { Cancel, Throw, OutOfMemory };

// Runs with a callback that faults at call `at` of the `occurrence`-th run of `phase`
// (phases can recur, e.g. smoothing); returns the attempt and how many calls followed the fault.
Attempt run_with_fault(const PointSet& in, const RunSetup& s, const std::string& phase,
                       int occurrence, int at, Fault fault, int& calls_after) {
    int seen_occurrence = 0, seen_calls = 0;
    std::string current;
    bool faulted = false;
    calls_after = 0;
    Progress progress([&](const std::string& p, double) -> bool {
        if (faulted) {
            ++calls_after;
            return true;
        }
        if (p != current) {
            current = p;
            seen_calls = 0;
            if (p == phase) ++seen_occurrence;
        }
        ++seen_calls;
        if (p != phase || seen_occurrence != occurrence || seen_calls != at) return true;
        faulted = true;
        if (fault == Fault::Throw) throw std::runtime_error("callback failed in " + phase);
        if (fault == Fault::OutOfMemory) throw std::bad_alloc();
        return false;
    });
    rsr::Observer observer;
    return attempt(in, s.method, {}, {1, &progress}, s.observed ? &observer : nullptr);
}

// Every phase, at its first call (the phase boundary) and at its last (inside its loop). One
// thread, so that the calls are the same in every run (parallel loops report from the calling
// thread after each of its chunks); a phase seen in an earlier setup is not checked again.
TEST(Faults, CancelThrowOrOutOfMemoryInEveryPhaseStopsAtOnce) {
    std::set<std::string> checked;
    for (const RunSetup& s : setups()) {
        const PointSet in = cloud(s);
        const Attempt reference = attempt(in, s.method);
        std::map<std::string, int> occurrences;
        for (const auto& [phase, calls] : phase_calls(in, s)) {
            const int occurrence = ++occurrences[phase];
            const std::string key = std::string(name(s.method)) + (s.normals ? "+" : "-") + phase +
                                    std::to_string(occurrence);
            if (!checked.insert(key).second) continue;
            for (int at : {1, calls}) {
                const std::string where = s.label() + ", " + phase + " #" +
                                          std::to_string(occurrence) + ", call " +
                                          std::to_string(at) + " of " + std::to_string(calls);
                int after = 0;
                Attempt a = run_with_fault(in, s, phase, occurrence, at, Fault::Cancel, after);
                testing::expect_error(a, Attempt::Cancel, "cancelled", where);
                EXPECT_EQ(after, 0) << where;
                EXPECT_TRUE(a.mesh.triangles.empty()) << where;
                if (at == 1 && calls > 1) continue; // the other faults in the loop only
                a = run_with_fault(in, s, phase, occurrence, at, Fault::Throw, after);
                testing::expect_error(a, Attempt::OtherError, "callback failed in " + phase, where);
                EXPECT_EQ(after, 0) << where;
                a = run_with_fault(in, s, phase, occurrence, at, Fault::OutOfMemory, after);
                testing::expect_error(a, Attempt::OtherError, "bad_alloc", where);
                EXPECT_EQ(after, 0) << where;
            }
        }
        // Nothing is left over from the failed runs.
        EXPECT_TRUE(testing::same_connectivity(attempt(in, s.method).mesh, reference.mesh))
            << s.label();
    }
    // Every phase name of both methods, with and without input normals, was cancelled.
    std::set<std::string> phases;
    for (const std::string& key : checked) phases.insert(key.substr(0, key.size() - 1));
    for (const char* phase : {"hrsr+validation",        "hrsr+normal check",
                              "hrsr+collapse graph",    "hrsr+collapse",
                              "hrsr+smoothing",         "hrsr+small components",
                              "hrsr+candidate graph",   "hrsr+spanning tree",
                              "hrsr+face split",        "hrsr+handles",
                              "hrsr+ear triangulation", "hrsr+re-expansion",
                              "hrsr+assembly",          "hrsr-normal estimation",
                              "hrsr-neighbour graph",   "hrsr-normal orientation",
                              "rsr+component split",    "rsr-normal orientation",
                              "rsr+assembly",           "rsr+small components"})
        EXPECT_TRUE(phases.count(phase)) << phase;
}

// Cancelling from the calling thread while a worker runs a parallel loop stops the loop. The
// worker waits until the caller has reported once, so that the caller surely runs a chunk (a
// loaded machine may otherwise let the worker run them all before the caller starts).
TEST(Faults, CancelDuringAParallelLoopStopsIt) {
    std::atomic<bool> reported{false};
    Progress progress([&](const std::string&, double fraction) {
        if (fraction == 0) return true;
        reported = true;
        return false;
    });
    progress.begin("loop");
    std::atomic<std::size_t> done{0};
    EXPECT_THROW(parallel_for({2, &progress}, 1000000,
                              [&](std::size_t) {
#ifdef _OPENMP
                                  while (omp_get_thread_num() != 0 && !reported)
                                      std::this_thread::yield();
#endif
                                  ++done;
                              }),
                 Cancelled);
    EXPECT_TRUE(reported);
    EXPECT_LT(done.load(), 1000000u);
}

// D-43: a cloud of three tiles replays most of its records by tile in parallel; progress is
// still reported from the calling thread while the tiles run, a cancel there stops the
// replay, and a run after it gives the same mesh as before.
TEST(Faults, CancelWhileTheTilesReplayStopsThem) {
    const PointSet in = testing::sample_torus(150000, 1.0, 0.3, testing::Density::Graded);
    const Attempt reference = attempt(in, Method::Hrsr, {}, {2, nullptr});
    ASSERT_EQ(reference.kind, Attempt::Mesh) << reference.message;
    ASSERT_GT(reference.report.reexpansion.replayed_in_tiles,
              reference.report.reexpansion.records / 2);
    std::vector<double> fractions;
    Progress counting([&](const std::string& phase, double fraction) {
        if (phase == "re-expansion") fractions.push_back(fraction);
        return true;
    });
    ASSERT_EQ(attempt(in, Method::Hrsr, {}, {2, &counting}).kind, Attempt::Mesh);
    // Calls all through the phase, never going back.
    ASSERT_GE(fractions.size(), 20u);
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end()));
    EXPECT_GT(fractions.back(), 0.9);
    int calls = 0, after = 0;
    Progress cancelling([&](const std::string& phase, double fraction) {
        if (calls < 0) {
            ++after;
            return true;
        }
        if (phase != "re-expansion" || fraction < 0.5) return true;
        calls = -1;
        return false;
    });
    const Attempt cancelled = attempt(in, Method::Hrsr, {}, {2, &cancelling});
    testing::expect_error(cancelled, Attempt::Cancel, "cancelled", "re-expansion in tiles");
    EXPECT_EQ(after, 0);
    EXPECT_TRUE(testing::same_connectivity(attempt(in, Method::Hrsr, {}, {2, nullptr}).mesh,
                                           reference.mesh));
}

// Prompt cancellation: on a cloud where a run takes seconds, no stretch without a progress call
// (where a cancel request would wait) takes more than a quarter of the run, the end included.
// Measured in CPU time of the process, so that other load on the machine does not count.
double cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

TEST(Faults, CancellationPointsAreNeverFarApart) {
    const PointSet in = testing::without_normals(testing::sample_torus(30000));
    for (Method m : kMethods) {
        const double start = cpu_seconds();
        double last = start, longest = 0;
        std::string where;
        Progress progress([&](const std::string& phase, double) {
            const double now = cpu_seconds();
            if (now - last > longest) {
                longest = now - last;
                where = phase;
            }
            last = now;
            return true;
        });
        const Attempt a = attempt(in, m, {}, {0, &progress});
        ASSERT_EQ(a.kind, Attempt::Mesh) << a.message;
        const double end = cpu_seconds();
        if (end - last > longest) {
            longest = end - last;
            where = "after the last call";
        }
        EXPECT_LT(longest, 0.25 * (end - start))
            << name(m) << ": " << longest << " s of " << end - start
            << " s without a progress call, ending in " << where;
    }
}

} // namespace
} // namespace hrsr
