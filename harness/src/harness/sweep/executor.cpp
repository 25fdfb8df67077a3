#include "harness/sweep/executor.hpp"

#include <atomic>
#include <exception>
#include <mutex>
#include <thread>

#include "harness/backends/subprocess.hpp"

namespace harness {

namespace {

class InProcessExecutor final : public SweepExecutor {
 public:
  std::string name() const override { return "this process"; }
  void run(const SweepPlan& plan, const std::vector<std::size_t>& jobs) override {
    for (const std::size_t k : jobs) (void)run_job(plan, k);
  }
};

/// Workers take the next job until none is left; each job is a child process whose output goes to
/// its log. A run has no time limit here (a case's own duration ends it).
class LocalExecutor final : public SweepExecutor {
 public:
  LocalExecutor(std::string binary, int parallel, int threads) : binary_(std::move(binary)), parallel_(parallel), threads_(threads) {}
  std::string name() const override { return "this machine, " + std::to_string(parallel_) + " at a time"; }
  void run(const SweepPlan& plan, const std::vector<std::size_t>& jobs) override {
    std::atomic<std::size_t> next{0};
    std::mutex failed;
    std::exception_ptr first_error;  // a stop signal, say: raised again once every worker has ended
    const auto worker = [&] {
      try {
        for (std::size_t i = next++; i < jobs.size() && !first_error; i = next++) {
          const std::size_t k = jobs[i];
          const std::vector<std::string> argv = {binary_, "job", plan.file().string(), std::to_string(k), "--threads",
                                                 std::to_string(threads_)};
          (void)run_process(argv, {}, plan.dir, plan.log(k), 0.0);
        }
      } catch (...) {
        const std::lock_guard<std::mutex> lock(failed);
        if (!first_error) first_error = std::current_exception();
      }
    };
    std::vector<std::thread> workers;
    for (int w = 0; w < parallel_ && std::size_t(w) < jobs.size(); ++w) workers.emplace_back(worker);
    for (auto& t : workers) t.join();
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
