// damseis_fuzz: feeds mutated inputs to the readers of user input and checks
// that each one is either accepted with finite values or refused with one
// clean line; a crash, a hang (an input taking longer than --timeout) or a
// broken promise is a finding, saved to --failures for reproduction.
//   damseis_fuzz --target case_gravity --runs 100000 --seed 1
//   damseis_fuzz --target all --runs 2000
//   damseis_fuzz --target case_arch --replay FILE
// Exit code: 0 no finding, 1 findings (or a crash/hang), 2 bad arguments.
#include "mutator.h"
#include "targets.h"
#include <CLI/CLI.hpp>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <damseis/results/progress.h>
#include <fcntl.h>
#include <fstream>
#include <mpi.h>
#include <sstream>
#include <unistd.h>

namespace
{
using namespace damseis::fuzz;
namespace fs = std::filesystem;

// What the signal handler needs: the input being run and where to save it.
const std::string* current_input = nullptr;
char crash_file[4096] = {};
const char* crash_reason = "";

/// Async-signal-safe name of the signals handled.
const char* signal_name(int sig)
{
  switch (sig)
  {
  case SIGALRM:
    return "hang (timeout)";
  case SIGSEGV:
    return "segmentation fault";
  case SIGABRT:
    return "abort";
  case SIGFPE:
    return "floating-point exception";
  case SIGBUS:
    return "bus error";
  case SIGILL:
    return "illegal instruction";
  default:
    return "signal";
  }
}

void save_and_exit(int sig)
{
  const char* what = signal_name(sig);
  const int fd = ::open(crash_file, O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd >= 0 && current_input)
  {
    [[maybe_unused]] auto n =
        ::write(fd, current_input->data(), current_input->size());
    ::close(fd);
  }
  const char* parts[] = {
      "damseis_fuzz: FINDING: ", what,       " (", crash_reason,
      "); input saved to ",      crash_file, "\n"};
  for (const char* p : parts)
  {
    [[maybe_unused]] auto n = ::write(2, p, std::strlen(p));
  }
  ::_exit(1);
}

void install_handlers()
{
  // An alternate stack, so that a stack overflow is reported too.
  static std::vector<char> stack(1 << 16);
  stack_t ss{};
  ss.ss_sp = stack.data();
  ss.ss_size = stack.size();
  sigaltstack(&ss, nullptr);
  struct sigaction sa
  {
  };
  sa.sa_handler = save_and_exit;
  sa.sa_flags = SA_ONSTACK;
  for (int sig : {SIGSEGV, SIGABRT, SIGFPE, SIGBUS, SIGILL, SIGALRM})
    sigaction(sig, &sa, nullptr);
}

struct Tally
{
  long accepted = 0, rejected = 0, findings = 0;
  double slowest = 0.0;
};

Tally fuzz(const Target& t, long runs, std::uint64_t seed, int timeout,
           const fs::path& failures, const fs::path& scratch)
{
  Mutator mutator(seed, t.seeds, t.dictionary, t.keys, t.binary);
  const std::string crash =
      (failures / ("crash-" + t.name + "-seed" + std::to_string(seed)))
          .string();
  std::snprintf(crash_file, sizeof crash_file, "%s", crash.c_str());
  crash_reason = t.name.c_str();
  Tally tally;
  // The seeds themselves first, then mutations.
  for (long i = 0; i < runs; ++i)
  {
    const std::string input = i < static_cast<long>(t.seeds.size())
                                  ? t.seeds[static_cast<std::size_t>(i)]
                                  : mutator.next();
    current_input = &input;
    const auto start = std::chrono::steady_clock::now();
    alarm(static_cast<unsigned>(timeout));
    try
    {
      if (t.run(input, scratch) == Outcome::accepted)
        ++tally.accepted;
      else
        ++tally.rejected;
    }
    catch (const Finding& f)
    {
      const auto file = failures / (t.name + "-seed" + std::to_string(seed) +
                                    "-input" + std::to_string(i));
      std::ofstream(file, std::ios::binary) << input;
      std::fprintf(stderr,
                   "damseis_fuzz: FINDING in %s: %s; input saved to %s\n",
                   t.name.c_str(), f.what(), file.c_str());
      ++tally.findings;
    }
    alarm(0);
    current_input = nullptr; // `input` ends with this iteration
    tally.slowest = std::max(
        tally.slowest,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
            .count());
  }
  current_input = nullptr;
  return tally;
}
} // namespace

int main(int argc, char** argv)
{
  CLI::App app{"damseis_fuzz: mutation fuzzing of the readers of user input"};
  std::string which = "all", replay;
  long runs = 2000;
  std::uint64_t seed = 1;
  int timeout = 20;
  std::string failures = ".", source = DAMSEIS_SOURCE_DIR;
  app.add_option("--target", which,
                 "target name, names separated by commas, or all")
      ->capture_default_str();
  app.add_option("--runs", runs, "inputs per target (seeds included)")
      ->check(CLI::Range(1L, 100000000L))
      ->capture_default_str();
  app.add_option("--seed", seed, "random seed")->capture_default_str();
  app.add_option("--timeout", timeout, "seconds one input may take")
      ->check(CLI::Range(1, 3600))
      ->capture_default_str();
  app.add_option("--failures", failures, "folder for inputs that fail")
      ->capture_default_str();
  app.add_option("--replay", replay, "run this one input file and report");
  bool list = false;
  app.add_flag("--list", list, "list the targets and exit");
  CLI11_PARSE(app, argc, argv);

  // The readers print warnings on MPI rank 0 (results::warn): MPI is
  // initialised, and stdout (the warnings) goes to /dev/null; reports go to
  // stderr.
  MPI_Init(&argc, &argv);
  // DOLFINx's INFO lines (meshes read by the dam_model target) off.
  damseis::results::quiet_library_logging();
  const fs::path scratch =
      fs::temp_directory_path() / ("damseis_fuzz." + std::to_string(getpid()));
  int status = 0;
  try
  {
    fs::create_directories(failures);
    const auto targets = all_targets(source, scratch);
    if (list)
    {
      for (const auto& t : targets)
        std::printf("%-20s %s (%zu seeds)\n", t.name.c_str(), t.help.c_str(),
                    t.seeds.size());
    }
    else
    {
      std::fflush(stdout);
      if (!std::freopen("/dev/null", "w", stdout))
        throw std::runtime_error("cannot silence stdout");
      install_handlers();
      bool found = false;
      for (const auto& t : targets)
      {
        if (which != "all" &&
            ("," + which + ",").find("," + t.name + ",") == std::string::npos)
          continue;
        found = true;
        if (!replay.empty())
        {
          std::ifstream in(replay, std::ios::binary);
          std::ostringstream bytes;
          bytes << in.rdbuf();
          Target one = t;
          one.seeds = {bytes.str()};
          const auto r = fuzz(one, 1, seed, timeout, failures, scratch);
          std::fprintf(stderr, "%s: %s\n", replay.c_str(),
                       r.findings   ? "FINDING"
                       : r.accepted ? "accepted"
                                    : "rejected with one line");
          status = r.findings ? 1 : 0;
          continue;
        }
        const auto start = std::chrono::steady_clock::now();
        const auto r = fuzz(t, runs, seed, timeout, failures, scratch);
        const double seconds = std::chrono::duration<double>(
                                   std::chrono::steady_clock::now() - start)
                                   .count();
        std::fprintf(stderr,
                     "%-20s %ld inputs (seed %llu) in %.1f s: %ld accepted, "
                     "%ld refused with one line, %ld findings; slowest input "
                     "%.3f s\n",
                     t.name.c_str(), runs,
                     static_cast<unsigned long long>(seed), seconds, r.accepted,
                     r.rejected, r.findings, r.slowest);
        if (r.findings)
          status = 1;
      }
      if (!found)
      {
        std::fprintf(stderr, "damseis_fuzz: unknown target %s; see --list\n",
                     which.c_str());
        status = 2;
      }
    }
  }
  catch (const std::exception& e)
  {
    std::fprintf(stderr, "damseis_fuzz: %s\n", e.what());
    status = 2;
  }
  std::error_code ec;
  fs::remove_all(scratch, ec);
  MPI_Finalize();
  return status;
}
