#include "regression/case_workers.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace qs {

CaseWorkers case_workers(int requested, std::size_t cases) {
    const int cores = int(std::max(1u, std::thread::hardware_concurrency()));
    CaseWorkers w;
    w.jobs = std::clamp(requested > 0 ? requested : cores, 1, std::max(1, int(cases)));
    w.threads = std::max(1, cores / w.jobs);
    return w;
}

void run_cases(int jobs, std::size_t cases, const std::function<bool(int worker, std::size_t k)>& run) {
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    auto worker = [&](int id) {
        for (std::size_t k = next++; k < cases && !stop; k = next++) {
            if (!run(id, k)) stop = true;
        }
    };
    std::vector<std::thread> pool;
    for (int j = 1; j < jobs; ++j) pool.emplace_back(worker, j);
    worker(0);
    for (std::thread& t : pool) t.join();
}

}  // namespace qs
