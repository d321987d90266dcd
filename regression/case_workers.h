#pragma once
// The cases of a check or a golden-image suite, run a few at once. A case is a whole render (for a
// check also a quadshade-reference process) with threads of its own, so the cases run on plain
// threads, one per job, not on TBB's: a render limits TBB's threads to its share of the cores
// (core/parallel.h's ThreadLimit holds for the whole process), which would limit the cases too,
// and a TBB thread waiting for a render's tiles may take up another case in the meantime.

#include <cstddef>
#include <functional>

namespace qs {

struct CaseWorkers {
    int jobs = 1;     // cases at once
    int threads = 1;  // each case's render: the cores shared among the jobs
};
// `requested` cases at once (0: one per core), at least one and at most one per case.
CaseWorkers case_workers(int requested, std::size_t cases);

// Calls run(worker, k) for the cases k = 0, 1, ... in order on `jobs` threads (the caller's one of
// them, worker 0; the others 1 to jobs - 1), each taking the next case when it is done with one,
// until every case is taken or a call returns false.
void run_cases(int jobs, std::size_t cases, const std::function<bool(int worker, std::size_t k)>& run);

}  // namespace qs
