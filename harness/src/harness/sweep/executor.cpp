#include "harness/sweep/executor.hpp"

#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>

#include "harness/backends/subprocess.hpp"
#include "harness/sweep/sweep_progress.hpp"

namespace harness {

namespace {

class InProcessExecutor final : public SweepExecutor {
 public:
  std::string name() const override { return "this process"; }
  void run(const SweepPlan& plan, const std::vector<std::size_t>& jobs) override {
    SweepProgress progress(progress_, jobs.size());
    std::size_t ended = 0, failed = 0;
    for (const std::size_t k : jobs) {
      progress.update(ended, failed, 1, job_title(plan.jobs[k]));
      // Each run's own line (redrawn on a terminal, or every --progress-every seconds) as it goes.
      failed += !run_job(plan, k, progress_.mode == silodem::ProgressMode::Off ? -1.0
                                  : progress_.mode == silodem::ProgressMode::Log ? progress_.every_seconds : 0.0);
      ++ended;
    }
    progress.finish(ended, failed);
  }
};

/// Workers take the next job until none is left, the longest expected first (job_plan.hpp); each job
/// is a child process whose output goes to its log. A run has no time limit here (a case's own
/// duration ends it).
class LocalExecutor final : public SweepExecutor {
 public:
  LocalExecutor(std::string binary, int parallel, int threads) : binary_(std::move(binary)), parallel_(parallel), threads_(threads) {}
  std::string name() const override { return "this machine, " + std::to_string(parallel_) + " at a time"; }
  void run(const SweepPlan& plan, const std::vector<std::size_t>& listed) override {
    const std::vector<std::size_t> jobs = longest_first(plan, listed);
    std::atomic<std::size_t> next{0}, ended{0}, failed{0};
    std::mutex guard;
    std::exception_ptr first_error;  // a stop signal, say: raised again once every worker has ended
    std::atomic<bool> stop{false};   // set once first_error is (read without the lock)
    const auto worker = [&] {
      try {
        for (std::size_t i = next++; i < jobs.size() && !stop; i = next++) {
          const std::size_t k = jobs[i];
          // The run's progress goes to the job's log, a plain line every 30 s.
          const std::vector<std::string> argv = {binary_, "job", plan.file().string(), std::to_string(k), "--threads",
                                                 std::to_string(threads_), "--progress-every", "30"};
          failed += run_process(argv, {}, plan.dir, plan.log(k), 0.0).exit_status != 0;
          ++ended;
        }
      } catch (...) {
        const std::lock_guard<std::mutex> lock(guard);
        if (!first_error) first_error = std::current_exception();
        stop = true;
      }
    };
    SweepProgress progress(progress_, jobs.size());
    std::vector<std::thread> workers;
    for (int w = 0; w < parallel_ && std::size_t(w) < jobs.size(); ++w) workers.emplace_back(worker);
    while (ended < jobs.size() && !stop) {
      std::this_thread::sleep_for(std::chrono::milliseconds(200));
      const std::size_t e = ended;
      progress.update(e, failed, std::min<std::size_t>(std::size_t(parallel_), jobs.size() - e), "");
    }
    for (auto& t : workers) t.join();
    progress.finish(ended, failed);
    if (first_error) std::rethrow_exception(first_error);
  }

 private:
  std::string binary_;
  int parallel_, threads_;
};

}  // namespace

std::unique_ptr<SweepExecutor> in_process_executor() { return std::make_unique<InProcessExecutor>(); }

std::unique_ptr<SweepExecutor> local_executor(std::string silodem_binary, int parallel, int threads_per_job) {
  return std::make_unique<LocalExecutor>(std::move(silodem_binary), std::max(1, parallel), std::max(1, threads_per_job));
}

}  // namespace harness
