#include <sys/wait.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <stdexcept>
#include <thread>

#include "harness/backends/subprocess.hpp"
#include "harness/sweep/executor.hpp"

#include <fstream>
#include "harness/sweep/sweep_progress.hpp"
#include "silodem/core/interrupt.hpp"
#include "silodem/output/checked_file.hpp"

namespace harness {

namespace {

struct Captured {
  int status = -1;
  std::string output;
};

/// A command's exit status and its stdout and stderr together.
Captured capture(const std::string& command) {
  Captured c;
  FILE* pipe = ::popen((command + " 2>&1").c_str(), "r");
  if (!pipe) throw std::runtime_error("cannot run " + command);
  std::array<char, 4096> buf{};
  while (std::fgets(buf.data(), int(buf.size()), pipe)) c.output += buf.data();
  const int s = ::pclose(pipe);
  c.status = WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  return c;
}

class SlurmExecutor final : public SweepExecutor {
 public:
  SlurmExecutor(std::string binary, SlurmOptions o) : binary_(std::move(binary)), o_(std::move(o)) {}
  std::string name() const override { return "Slurm (sbatch --array)"; }

  void run(const SweepPlan& plan, const std::vector<std::size_t>& jobs) override {
    if (jobs.empty()) return;
    std::string indices;
    for (const std::size_t k : jobs) indices += (indices.empty() ? "" : ",") + std::to_string(k);
    const std::string threads = std::to_string(std::max(1, o_.threads_per_job));
    const std::filesystem::path script = plan.dir / "sweep.sbatch";
    silodem::write_file_checked(script, "#!/bin/sh\n"
                                        "# Written by silodem: one array task per job of " + plan.file().string() + "\n"
                                        "#SBATCH --job-name=silodem-sweep\n"
                                        "#SBATCH --array=" + indices + "\n"
                                        "#SBATCH --cpus-per-task=" + threads + "\n"
                                        "#SBATCH --output=" + (plan.dir / "jobs" / "%a.log").string() + "\n"
                                        "exec " + shell_quote(binary_) + " job " + shell_quote(plan.file().string()) +
                                        " \"$SLURM_ARRAY_TASK_ID\" --threads " + threads + " --progress-every 30\n");
    std::string cmd = "sbatch --parsable";
    for (const auto& a : o_.sbatch_args) cmd += " " + shell_quote(a);
    const Captured sub = capture(cmd + " " + shell_quote(script.string()));
    if (sub.status != 0) throw std::runtime_error("sbatch refused the sweep (" + cmd + "): " + sub.output);
    const std::string id = sub.output.substr(0, sub.output.find_first_of(";\n"));
    std::fprintf(stderr, "[sweep] submitted %zu jobs as Slurm array %s\n", jobs.size(), id.c_str());
    SweepProgress progress(progress_, jobs.size());
    std::size_t failed = 0;
    const auto ended = [&] {  // a job's status file appears when it ends, done or failed
      std::size_t n = 0;
      failed = 0;
      for (const std::size_t k : jobs) {
        std::ifstream status(plan.status(k));
        if (!status) continue;
        ++n;
        const std::string text((std::istreambuf_iterator<char>(status)), std::istreambuf_iterator<char>());
        failed += text.find("\"failed\"") != std::string::npos;
      }
      return n;
    };
    while (true) {
      if (const int sig = silodem::stop_signal()) {
        (void)capture("scancel " + shell_quote(id));
        throw silodem::Interrupted(sig, "interrupted by " + silodem::signal_name(sig) + " while Slurm array " + id +
                                            " ran (cancelled; finished jobs keep their results)");
      }
      const Captured q = capture("squeue -h -j " + shell_quote(id) + " -o %i");
      // squeue forgets a finished array after MinJobAge and then calls its id invalid.
      if ((q.status == 0 && q.output.find_first_not_of(" \n") == std::string::npos) ||
          q.output.find("Invalid job id") != std::string::npos) {
        const std::size_t e = ended();
        progress.finish(e, failed);
        return;
      }
      if (q.status == 0) {
        std::size_t queued = 0;  // squeue lists one line per array task still pending or running
        for (const char c : q.output) queued += c == '\n';
        const std::size_t e = ended();
        progress.update(e, failed, queued, "Slurm array " + id);
      }
      if (q.status != 0) throw std::runtime_error("squeue failed while waiting for array " + id + ": " + q.output);
      std::this_thread::sleep_for(std::chrono::duration<double>(o_.poll_seconds));
    }
  }

 private:
  std::string binary_;
  SlurmOptions o_;
};

}  // namespace

std::unique_ptr<SweepExecutor> slurm_executor(std::string silodem_binary, SlurmOptions options) {
  return std::make_unique<SlurmExecutor>(std::move(silodem_binary), std::move(options));
}

}  // namespace harness
