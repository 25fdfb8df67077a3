// silodem — command-line entry point. Exit codes: 0 success, 1 a verification check failed,
// 2 bad input (case file or command line), 3 the run could not continue (out of memory too),
// 4 internal error.
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>
#include <algorithm>
#include <memory>
#include <new>
#include <sstream>
#include <thread>
#include <string>
#include <vector>

#include "harness/compare.hpp"
#include "harness/sweep/executor.hpp"
#include "harness/sweep/job_plan.hpp"
#include "harness/verdict_report.hpp"
#include "harness/verify.hpp"
#include "silodem/case/case_error.hpp"
#include "silodem/case/case_loader.hpp"
#include "silodem/case/memory_estimate.hpp"
#include "silodem/core/progress.hpp"
#include "silodem/checkpoint/archive.hpp"
#include "silodem/core/interrupt.hpp"
#include "silodem/core/job_stop.hpp"
#include "silodem/core/parallel.hpp"
#include "silodem/output/manifest.hpp"
#include "silodem/output/result_dir.hpp"
#include "silodem/run/simulation.hpp"

namespace fs = std::filesystem;

namespace {

/// This program's own path, for the commands that run it again (a sweep's jobs).
std::string self_binary() {
  std::error_code ec;
  const fs::path p = fs::read_symlink("/proc/self/exe", ec);
  return ec ? std::string("silodem") : p.string();
}

/// Words separated by blanks (sbatch's options as one command-line argument).
std::vector<std::string> split_words(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string w; in >> w;) out.push_back(w);
  return out;
}

const char* kUsage =
    "usage: silodem <command> [options]\n"
    "\n"
    "commands:\n"
    "  run      run one case and write its result files\n"
    "  verify   run cases with their verification checks and print a verdict table\n"
    "  compare  run cases in silodem, LAMMPS, LIGGGHTS and YADE and compare them\n"
    "  check    validate case files without running them\n"
    "  job      run one job of a sweep's plan (what verify's executors call on each node)\n"
    "\n"
    "`silodem <command> --help` describes each command.\n";

const char* kRunHelp =
    "usage: silodem run CASE.json --out DIR [--threads N] [--restart] [--quiet]\n"
    "\n"
    "Runs the case and writes DIR/summary.json (inputs echoed, derived constants, run statistics,\n"
    "final energy balance), DIR/series.csv (energy ledger, ball count, max overlap, wall force\n"
    "over time), DIR/probes/*.csv and, written last, DIR/manifest.json (every file's size and CRC-32).\n"
    "The run writes into DIR.partial-<pid> and renames it to DIR only when complete. An existing DIR\n"
    "is replaced only if silodem wrote it (it carries .silodem-result.json); anything else, the working\n"
    "directory or a directory holding the case file is refused (exit 2). SIGTERM, SIGINT and SIGHUP\n"
    "stop the run at the end of the step (checkpointed if the case checkpoints; exit 128 + signal).\n"
    "  --threads N  threads for the force and integration loops (default 1); the results are\n"
    "               bitwise the same for any N\n"
    "  --restart    continue from the newest valid checkpoint in DIR.checkpoint/ (the case's\n"
    "               \"checkpoint\" section writes them); the results are bitwise those of an\n"
    "               uninterrupted run. A damaged checkpoint is refused with the reason and the\n"
    "               one before it used; none usable: exit 2\n"
    "  --progress-every S  a plain progress line every S seconds (simulated time, steps/s, ball-steps/s,\n"
    "               simulated s per s, time left), also when stderr is not a terminal; without it the\n"
    "               line is redrawn in place on a terminal and not written elsewhere\n"
    "  --quiet   no banner and no progress lines on stderr\n";

const char* kVerifyHelp =
    "usage: silodem verify CASE.json... [--out DIR] [--report FILE.md] [--threads N] [--material-tests-from FILE]\n"
    "                      [--jobs N | --slurm [--sbatch \"ARGS\"]] [--resume] [--quiet]\n"
    "\n"
    "Validates every case and every variant in its \"verify\" section, then runs them, compares\n"
    "the measured quantities with the closed-form oracles and prints one verdict line per case,\n"
    "variant and quantity. Writes DIR/verdicts.json (every row) and, with --report, a Markdown\n"
    "report. Exit status 1 if any check fails.\n"
    "  --out DIR       result root (default: results)\n"
    "  --report FILE   Markdown report to write\n"
    "  --threads N     threads for each of silodem's runs (default 1; bitwise the same results)\n"
    "  --jobs N        runs at a time on this machine, each a child process (default: the cores\n"
    "                  divided by --threads). The runs are the jobs of DIR/sweep/plan.json\n"
    "  --slurm         submit the jobs to Slurm as one job array (sbatch --array) and wait for it;\n"
    "                  DIR must be on a file system every node shares (docs/cluster.md)\n"
    "  --sbatch ARGS   options for sbatch, e.g. \"--partition=short --account=silo --time=01:00:00\"\n"
    "  --resume        keep results in DIR that are complete, verify against their manifests and\n"
    "                  were run from the same case input; run only the missing or failed ones\n"
    "  --material-tests-from FILE\n"
    "                  the verdicts.json of an earlier verify: a case whose checks take the virtual\n"
    "                  material tests (janssen_prediction, flow_pattern) takes those this command\n"
    "                  does not run from there\n"
    "  --progress-every S  the sweep's progress (jobs done, running, time left) as a plain line every\n"
    "                  S seconds, also when stderr is not a terminal (each job's log gets its run's line\n"
    "                  every 30 s)\n"
    "  --quiet         no progress lines on stderr\n";

const char* kCompareHelp =
    "usage: silodem compare CASE.json... [--out DIR] [--report FILE.md] [--codes a,b,...] [--threads N]\n"
    "                       [--ranks N [--launcher mpirun|srun]] [--jobs N | --slurm [--sbatch \"ARGS\"]] [--resume]\n"
    "                       [--quiet]\n"
    "\n"
    "Runs each case's \"compare\" variants in every code that can represent them (silodem, lammps,\n"
    "liggghts, yade), rebuilds every code's result files from its particle dumps, checks each code\n"
    "against theory, compares each reference code with silodem, and prints one verdict line per\n"
    "case, variant, code and quantity. A code that is not installed or cannot represent the case is\n"
    "reported as skipped with the reason, never as a pass; a crash or time-out is a failure with the\n"
    "tail of the code's log. Writes DIR/verdicts.json and, with --report, a Markdown report with the\n"
    "codes' energy ledgers side by side. Exit status 1 if any check fails.\n"
    "  --out DIR       result root (default: results/compare)\n"
    "  --report FILE   Markdown report to write\n"
    "  --codes LIST    only these codes (comma-separated)\n"
    "  --threads N     threads for silodem's own runs (default 1)\n"
    "  --ranks N       MPI ranks for LAMMPS and LIGGGHTS (default 1; YADE runs on one process)\n"
    "  --launcher L    mpirun (default: mpirun -np N) or srun (srun -n N, inside a Slurm allocation)\n"
    "  --jobs N        runs at a time on this machine (default 1, so that the run times compare);\n"
    "                  the runs are the jobs of DIR/sweep/plan.json: the shared states first, then\n"
    "                  every code's run and the seed-scatter runs\n"
    "  --slurm         each of the two rounds as one Slurm job array; --sbatch ARGS as for verify\n"
    "  --resume        keep the runs in DIR that finished from the same inputs (the case file's bytes,\n"
    "                  the job, --ranks and --launcher) and whose results verify against their\n"
    "                  manifests; run only the others. A long compare stopped part way goes on so\n"
    "                  (not across a change of the silodem build or of a reference code)\n"
    "  --progress-every S  the sweep's progress (jobs done, running, time left) as a plain line every\n"
    "                  S seconds, also when stderr is not a terminal (each job's log gets its run's line\n"
    "                  every 30 s)\n"
    "  --quiet         no progress lines on stderr\n";

const char* kCheckHelp =
    "usage: silodem check CASE.json|RESULT_DIR...\n"
    "\n"
    "Loads and validates each case file, including its \"verify\" and \"compare\" variants and checks; prints the\n"
    "derived per-ball constants. Exit 2 on the first invalid file, with the JSON path of the\n"
    "offending field. A result directory (one carrying .silodem-result.json) is checked against its\n"
    "manifest (every file's size and CRC-32): exit 1 if it does not verify or is not a complete\n"
    "result.\n";

struct Args {
  std::vector<std::string> positional;
  std::string out, report, codes, material_tests_from, sbatch, launcher = "mpirun";
  int threads = 1, jobs = 0, ranks = 1;  // jobs 0: the cores divided by the threads
  double progress_every = 0.0;           // --progress-every S (0: redrawn on a terminal only)
  bool quiet = false, help = false, restart = false, slurm = false, resume = false;
};

/// A whole number from 1 to 999 for `option`.
int count_option(const std::string& option, const std::string& v) {
  if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos || v.size() > 3 || std::stoi(v) < 1)
    throw silodem::CaseError("command line", option + " needs a whole number from 1 to 999, not \"" + v + "\"");
  return std::stoi(v);
}

/// A number of seconds from 0.1 to 86400 for `option`.
double seconds_option(const std::string& option, const std::string& v) {
  char* end = nullptr;
  const double x = std::strtod(v.c_str(), &end);
  if (v.empty() || *end != '\0' || !(x >= 0.1 && x <= 86400.0))
    throw silodem::CaseError("command line", option + " needs seconds from 0.1 to 86400, not \"" + v + "\"");
  return x;
}

Args parse(int argc, char** argv, int first, bool takes_report, bool takes_codes = false) {
  Args a;
  for (int i = first; i < argc; ++i) {
    const std::string s = argv[i];
    if (s == "--help" || s == "-h") a.help = true;
    else if (s == "--quiet") a.quiet = true;
    else if (s == "--restart") a.restart = true;
    else if (s == "--out" && i + 1 < argc) a.out = argv[++i];
    else if (s == "--threads" && i + 1 < argc) a.threads = count_option(s, argv[++i]);
    else if (s == "--progress-every" && i + 1 < argc) a.progress_every = seconds_option(s, argv[++i]);
    else if (takes_report && s == "--jobs" && i + 1 < argc) a.jobs = count_option(s, argv[++i]);
    else if (takes_report && s == "--slurm") a.slurm = true;
    else if (takes_report && s == "--sbatch" && i + 1 < argc) a.sbatch = argv[++i];
    else if (takes_report && s == "--resume") a.resume = true;
    else if (takes_report && s == "--report" && i + 1 < argc) a.report = argv[++i];
    else if (takes_codes && s == "--codes" && i + 1 < argc) a.codes = argv[++i];
    else if (takes_codes && s == "--ranks" && i + 1 < argc) a.ranks = count_option(s, argv[++i]);
    else if (takes_codes && s == "--launcher" && i + 1 < argc) a.launcher = argv[++i];
    else if (takes_report && !takes_codes && s == "--material-tests-from" && i + 1 < argc) a.material_tests_from = argv[++i];
    else if (s.rfind("--", 0) == 0) throw silodem::CaseError("command line", "unknown or incomplete option " + s);
    else a.positional.push_back(s);
  }
  return a;
}

/// verify and compare: the result root and the report checked before anything runs; the root
/// created and marked, the report's folder created.
void prepare_outputs(const fs::path& root, const fs::path& report, const std::vector<fs::path>& inputs) {
  silodem::check_output_dir(root, inputs, "--out");
  if (!report.empty()) silodem::check_output_file(report, inputs, "--report");
  silodem::make_root(root);
  if (report.has_parent_path()) {
    std::error_code ec;
    fs::create_directories(report.parent_path(), ec);
    if (ec) throw silodem::WriteError(report.parent_path(), "cannot create the report's folder: " + ec.message());
  }
}

/// The executor the options ask for: Slurm, or `--jobs` child processes (default `parallel`).
std::unique_ptr<harness::SweepExecutor> make_executor(const Args& a, const std::string& binary, int parallel) {
  if (a.slurm && a.jobs) throw silodem::CaseError("command line", "--jobs runs on this machine; --slurm leaves it to Slurm");
  if (!a.slurm && !a.sbatch.empty()) throw silodem::CaseError("command line", "--sbatch is an option of --slurm");
  if (a.slurm) {
    harness::SlurmOptions so;
    so.sbatch_args = split_words(a.sbatch);
    so.threads_per_job = a.threads;
    return harness::slurm_executor(binary, so);
  }
  return harness::local_executor(binary, a.jobs ? a.jobs : parallel, a.threads);
}

int cmd_run(int argc, char** argv) {
  const Args a = parse(argc, argv, 2, false);
  if (a.help) return std::fputs(kRunHelp, stdout), 0;
  if (a.positional.size() != 1 || a.out.empty()) {
    std::fputs(kRunHelp, stderr);
    return 2;
  }
  const silodem::CaseConfig cfg = silodem::load_case_file(a.positional[0]);
  silodem::set_threads(a.threads);
  silodem::RunOptions opt{a.out, !a.quiet, !a.quiet};
  opt.progress_every = a.progress_every;
  opt.restart = a.restart;
  opt.inputs = {a.positional[0]};
  const auto summary = silodem::run_case(cfg, opt);
  std::printf("%s: %ld steps, t = %.6g s, stop: %s, %.3g s wall, energy drift %.3e -> %s\n", cfg.name.c_str(),
              summary["run"]["steps"].get<long>(), summary["run"]["time"].get<double>(),
              summary["run"]["stop_reason"].get<std::string>().c_str(), summary["run"]["wall_seconds"].get<double>(),
              summary["energy"]["relative_drift"].get<double>(), a.out.c_str());
  return 0;
}

int cmd_verify(int argc, char** argv) {
  const Args a = parse(argc, argv, 2, true);
  if (a.restart) throw silodem::CaseError("command line", "--restart is an option of run only");
  if (a.help) return std::fputs(kVerifyHelp, stdout), 0;
  if (a.positional.empty()) {
    std::fputs(kVerifyHelp, stderr);
    return 2;
  }
  silodem::set_threads(a.threads);
  harness::VerifyOptions opt;
  if (!a.out.empty()) opt.out_root = a.out;
  if (!a.report.empty()) opt.report = fs::path(a.report);
  if (!a.material_tests_from.empty()) opt.material_tests_from = fs::path(a.material_tests_from);
  opt.progress = !a.quiet;
  std::vector<fs::path> files(a.positional.begin(), a.positional.end());
  silodem::check_output_dir(opt.out_root, files, "--out");
  if (opt.report) silodem::check_output_file(*opt.report, files, "--report");
  opt.before_first_run = [&] { prepare_outputs(opt.out_root, opt.report ? *opt.report : fs::path(), files); };
  opt.silodem_binary = self_binary();
  opt.resume = a.resume;
  const int cores = std::max(1u, std::thread::hardware_concurrency());
  const auto executor = make_executor(a, opt.silodem_binary, std::max(1, cores / a.threads));
  if (!a.quiet) executor->set_progress(silodem::progress_style(a.progress_every));
  opt.executor = executor.get();
  const auto outcome = harness::verify_cases(files, opt);
  harness::print_verdicts(std::cout, outcome);
  harness::write_verdict_json(opt.out_root / "verdicts.json", outcome);
  if (opt.report) {
    harness::write_verdict_markdown(*opt.report, outcome, "Verification report",
                                    "Generated by `silodem verify` (see README): silodem alone, every integrator "
                                    "and time step of each case's `verify` section, against closed-form theory.");
  }
  return outcome.all_pass() ? 0 : 1;
}

int cmd_compare(int argc, char** argv) {
  const Args a = parse(argc, argv, 2, true, true);
  if (a.restart) throw silodem::CaseError("command line", "--restart is an option of run only");
  if (a.help) return std::fputs(kCompareHelp, stdout), 0;
  if (a.positional.empty()) {
    std::fputs(kCompareHelp, stderr);
    return 2;
  }
  silodem::set_threads(a.threads);
  harness::CompareOptions opt;
  if (!a.out.empty()) opt.out_root = a.out;
  if (a.launcher != "mpirun" && a.launcher != "srun")
    throw silodem::CaseError("command line", "--launcher is mpirun or srun, not \"" + a.launcher + "\"");
  opt.parallel = {a.ranks, a.launcher};
  opt.silodem_binary = self_binary();
  // One run at a time unless asked: the report's run times are each code alone on its core.
  const auto executor = make_executor(a, opt.silodem_binary, 1);
  if (!a.quiet) executor->set_progress(silodem::progress_style(a.progress_every));
  opt.executor = executor.get();
  opt.progress = !a.quiet;
  opt.resume = a.resume;
  for (std::size_t start = 0; !a.codes.empty() && start <= a.codes.size();) {
    const std::size_t end = std::min(a.codes.find(',', start), a.codes.size());
    opt.codes.push_back(a.codes.substr(start, end - start));
    start = end + 1;
  }
  const std::vector<fs::path> files(a.positional.begin(), a.positional.end());
  silodem::check_output_dir(opt.out_root, files, "--out");
  if (!a.report.empty()) silodem::check_output_file(a.report, files, "--report");
  opt.before_first_run = [&] { prepare_outputs(opt.out_root, a.report, files); };
  const auto outcome = harness::compare_cases(files, opt);
  harness::print_verdicts(std::cout, outcome);
  harness::write_verdict_json(opt.out_root / "verdicts.json", outcome);
  if (!a.report.empty()) {
    const fs::path report(a.report);
    harness::write_verdict_markdown(report, outcome, "Cross-code comparison",
                                    "Generated by `silodem compare` (see README): each case's `compare` variants in "
                                    "silodem, LAMMPS, LIGGGHTS and YADE, each against theory and each reference code "
                                    "against silodem. How each code represents the model: docs/reference-codes.md.");
  }
  return outcome.all_pass() ? 0 : 1;
}

/// `job PLAN K [--threads N]`: job K of a sweep's plan, run here (sweep/job_plan.hpp). Exit 0 when
/// the run is done, 3 when it failed (its status file says why).
int cmd_job(int argc, char** argv) {
  const Args a = parse(argc, argv, 2, false);
  if (a.help || a.positional.size() != 2) {
    std::fputs("usage: silodem job PLAN.json K [--threads N] [--progress-every S] [--quiet]\n\nRuns job K of a sweep's plan (silodem verify writes "
               "DIR/sweep/plan.json) and writes its status beside the plan.\n", a.help ? stdout : stderr);
    return a.help ? 0 : 2;
  }
  const harness::SweepPlan plan = harness::read_plan(a.positional[0]);
  const std::string& k = a.positional[1];
  if (k.empty() || k.find_first_not_of("0123456789") != std::string::npos || k.size() > 9)
    throw silodem::CaseError("command line", "the job number must be a whole number, not \"" + k + "\"");
  silodem::set_threads(a.threads);
  return harness::run_job(plan, std::size_t(std::stoul(k)), a.quiet ? -1.0 : a.progress_every) ? 0 : 3;
}

/// `check DIR`: the result directory against its manifest.
bool check_result_dir(const fs::path& dir) {
  const auto marker = silodem::read_marker(dir);
  const auto problems = silodem::verify_manifest(dir);
  if (problems.empty()) {
    std::printf("%s: complete and intact (%s, state %s, written %s by pid %ld: %s)\n", dir.c_str(),
                marker->kind.c_str(), marker->state.c_str(), marker->written.c_str(), marker->pid,
                marker->command.c_str());
    return marker->state == "complete";
  }
  std::printf("%s: does NOT verify (%s, state %s):\n", dir.c_str(), marker->kind.c_str(), marker->state.c_str());
  for (const auto& p : problems) std::printf("  %s\n", p.c_str());
  return false;
}

int cmd_check(int argc, char** argv) {
  const Args a = parse(argc, argv, 2, false);
  if (a.restart) throw silodem::CaseError("command line", "--restart is an option of run only");
  if (a.help) return std::fputs(kCheckHelp, stdout), 0;
  if (a.positional.empty()) {
    std::fputs(kCheckHelp, stderr);
    return 2;
  }
  for (const auto& f : a.positional) {
    if (fs::is_directory(f) && silodem::read_marker(f)) {  // a result directory: against its manifest
      if (!check_result_dir(f)) return 1;
      continue;
    }
    const auto cfg = silodem::load_case_file(f);
    const std::size_t runs = cfg.verify.is_null() ? 0 : harness::validate_verification(f);
    const std::size_t compare_runs = harness::validate_comparison(f);
    std::printf("%s: valid (case \"%s\", dt = %.6g s, %zu verification runs, %zu compare variants)\n", f.c_str(),
                cfg.name.c_str(), cfg.dt, runs, compare_runs);
    for (const auto& [name, m] : cfg.materials)
      if (cfg.contact.normal == silodem::NormalModel::Hertz)
        std::printf("  material %-12s E = %.6g Pa, nu = %.6g, zeta = %.6g (%s), mu = %.6g\n", name.c_str(), m.youngs_modulus,
                    m.poisson_ratio, m.hertz_damping_ratio, m.derived_from.c_str(), m.friction);
      else
        std::printf("  material %-12s k_i = %.6g N/m, c_i = %.6g N s/m (%s)%s\n", name.c_str(), m.k, m.c,
                    m.derived_from.c_str(),
                    cfg.contact.rotation() ? (", mu = " + std::to_string(m.friction) + ", mu_r = " +
                                              std::to_string(m.rolling_friction)).c_str()
                                           : "");
    std::printf("  memory estimate for a run: %s; limit %s\n", silodem::estimate_run_memory(cfg).describe().c_str(),
                silodem::run_memory_limit().source.c_str());
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h")) {
    std::fputs(kUsage, argc < 2 ? stderr : stdout);
    return argc < 2 ? 2 : 0;
  }
  const std::string cmd = argv[1];
  silodem::set_command_line(argc, argv);
  silodem::install_stop_signals();
  try {
    if (cmd == "run") return cmd_run(argc, argv);
    if (cmd == "verify") return cmd_verify(argc, argv);
    if (cmd == "compare") return cmd_compare(argc, argv);
    if (cmd == "check") return cmd_check(argc, argv);
    if (cmd == "job") return cmd_job(argc, argv);
    std::fprintf(stderr, "silodem: unknown command \"%s\"\n%s", cmd.c_str(), kUsage);
    return 2;
  } catch (const silodem::CaseError& e) {
    std::fprintf(stderr, "silodem: invalid input: %s\n", e.what());
    return 2;
  } catch (const silodem::CheckpointError& e) {
    std::fprintf(stderr, "silodem: %s\n", e.what());
    return 2;
  } catch (const silodem::RunError& e) {
    std::fprintf(stderr, "silodem: run stopped: %s\n", e.what());
    return 3;
  } catch (const silodem::JobStop& e) {
    std::fprintf(stderr, "silodem: %s\n", e.what());
    return e.exit_code();
  } catch (const std::bad_alloc&) {
    // Cases are refused beforehand when their estimate does not fit (case/memory_estimate.hpp);
    // this is the machine running short anyway (other processes, or an estimate too low).
    std::fprintf(stderr, "silodem: stopped: out of memory (more than the estimate `silodem check` prints, or other "
                         "processes took what was available)\n");
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "silodem: internal error: %s\n", e.what());
    return 4;
  }
}
