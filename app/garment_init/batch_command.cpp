// garment-init batch: every pattern of a folder through `run`, each in its own process (a crash or
// a runaway pattern cannot take the batch down; each gets a time limit), resumable, with a summary.

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include "batch_summary.h"
#include "command_line.h"
#include "commands.h"
#include "engine/body/default_body.h"
#include "engine/body/location_overrides.h"
#include "engine/core/atomic_file.h"
#include "engine/core/error.h"
#include "engine/core/input_file.h"
#include "engine/core/text.h"
#include "engine/io/sewn_export.h"
#include "engine/pattern/outfit.h"
#include "engine/pattern/pattern_files.h"
#include "engine/recovery/recovery.h"
#include "output_plan.h"

namespace garment::cli {
namespace {

struct Job {
  std::vector<std::filesystem::path> patterns;  // one, or an outfit's (the first innermost)
  std::filesystem::path body;
  std::string name;  // file stem; an outfit's garment names joined by '+'
};

// --outfits LIST: an outfit per line, its pattern files separated by spaces, the first innermost,
// and optionally a body (a file ending in .obj) for it; paths relative to the list's folder;
// blank lines and lines starting with # are skipped.
std::vector<Job> outfit_jobs(const std::filesystem::path& list,
                             const std::filesystem::path& fallback_body) {
  std::vector<Job> jobs;
  std::istringstream lines(read_file(list));
  std::string text;
  for (int number = 1; std::getline(lines, text); ++number) {
    std::istringstream words(text);
    std::string word;
    Job job{{}, fallback_body, {}};
    bool body_given = false;
    const std::string place = list.string() + ", line " + std::to_string(number);
    while (words >> word) {
      if (job.patterns.empty() && !body_given && word.starts_with("#")) break;
      const std::filesystem::path path = list.parent_path() / word;
      if (path.extension() == ".obj") {
        if (body_given) throw InputError(place + ": two bodies ('" + printable(word) + "')");
        job.body = path;
        body_given = true;
        continue;
      }
      job.patterns.push_back(path);
      if (!job.name.empty()) job.name += '+';
      job.name += outfit_garment_name(path);
    }
    if (job.patterns.empty()) {
      if (body_given) throw InputError(place + ": a body and no pattern");
      continue;
    }
    for (const std::filesystem::path& path : job.patterns)
      if (!std::filesystem::exists(path))
        throw InputError(place + ": no pattern file " + path.string());
    if (!std::filesystem::exists(job.body))
      throw InputError(place + ": no body file " + job.body.string());
    for (const Job& other : jobs)
      if (other.name == job.name)
        throw InputError(place + ": the outfit " + job.name + " is already in the list");
    jobs.push_back(std::move(job));
  }
  return jobs;
}

// index.json of GarmentCode datasets: file name → the body it was made for.
std::map<std::string, std::string> bodies_from_index(const std::filesystem::path& folder) {
  std::map<std::string, std::string> bodies;
  const std::filesystem::path index = folder / "index.json";
  if (!std::filesystem::exists(index)) return bodies;
  const nlohmann::json json = nlohmann::json::parse(read_file(index), nullptr, false);
  if (!json.is_object() || !json.contains("files") || !json["files"].is_array())
    throw InputError(index.string() + ": expected {\"files\": [{\"file\", \"body_obj\"}]}");
  for (const auto& entry : json["files"])
    if (entry.is_object() && entry.contains("file") && entry.contains("body_obj"))
      bodies[entry["file"].get<std::string>()] = entry["body_obj"].get<std::string>();
  return bodies;
}

std::filesystem::path self_executable() {
  return std::filesystem::read_symlink("/proc/self/exe");
}

Outcome read_outcome(const Job& job, const std::filesystem::path& report, int exit_code,
                     double seconds) {
  Outcome outcome;
  outcome.name = job.name;
  outcome.body = job.body.stem().string();
  outcome.seconds = seconds;
  const nlohmann::json json = nlohmann::json::parse(read_file(report), nullptr, false);
  if (json.is_discarded()) {
    outcome.status = "error";
    outcome.message = "unreadable report";
    return outcome;
  }
  outcome.status = exit_code == 0 ? "ok" : "fails";
  outcome.vertices = json.value("vertices", 0);
  outcome.pieces = json.value("pieces", 0);
  outcome.batches = static_cast<int>(json["batches"].size());
  outcome.revisits = json.value("revisits", 0);
  for (const auto& failure : json["quality"]["fails"])
    outcome.failures.push_back(failure.value("kind", "?"));
  if (json.contains("recovery") && json["recovery"].is_object()) {
    outcome.attempts =
        static_cast<int>(json["recovery"].value("attempts", nlohmann::json::array()).size());
    outcome.recovered = exit_code == 0 && json["recovery"].value("chosen", 0) > 0;
  }
  if (json.contains("cannot_fit") && json["cannot_fit"].is_object())
    outcome.cannot_fit = json["cannot_fit"].value("message", "");
  return outcome;
}

// The files one job writes into the output folder.
struct JobFiles {
  std::filesystem::path obj, report, log, outcome;
};

JobFiles job_files(const Job& job, const std::filesystem::path& output) {
  return {output / (job.name + ".obj"), output / (job.name + ".report.json"),
          output / (job.name + ".log"), output / (job.name + ".outcome.json")};
}

// Runs one job in a child process; returns its outcome (also written next to the output).
Outcome run_job(const Job& job, const std::filesystem::path& output, double time_limit,
                const std::string& parameters, const std::string& attempts,
                const std::string& exports, const std::string& clearance) {
  const JobFiles files = job_files(job, output);
  const std::filesystem::path& report = files.report;
  const std::filesystem::path& log = files.log;
  // Built before the fork: the child of a threaded process may only make async-signal-safe calls
  // until execv (another thread may hold the allocator's lock at the fork).
  const std::string exe = self_executable().string();
  std::vector<std::string> words = {exe, "run"};
  for (const std::filesystem::path& pattern : job.patterns)
    words.push_back(pattern.string());
  words.insert(words.end(), {"--body", job.body.string(), "-o", files.obj.string(), "--report",
                             report.string(), "--threads", "1", "--attempts", attempts, "--quiet"});
  if (!parameters.empty()) words.insert(words.end(), {"--parameters", parameters});
  if (!exports.empty()) words.insert(words.end(), {"--export", exports});
  if (!clearance.empty()) words.insert(words.end(), {"--clearance", clearance});
  std::vector<char*> argv;
  for (std::string& word : words)
    argv.push_back(word.data());
  argv.push_back(nullptr);
  const pid_t parent = ::getpid();
  const auto start = std::chrono::steady_clock::now();
  const pid_t child = ::fork();
  if (child == 0) {
    // The job dies with the batch (SIGTERM, SIGKILL, a crash): an orphan would keep writing its
    // files while a resumed batch runs the same job again. The signal is tied to this worker
    // thread, which waits for the job to end. A parent gone before prctl took effect is seen in
    // getppid(): the child was handed to another process.
    ::prctl(PR_SET_PDEATHSIG, SIGKILL);
    if (::getppid() != parent) ::_exit(127);
    const int descriptor = ::open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (descriptor >= 0) {
      ::dup2(descriptor, STDOUT_FILENO);
      ::dup2(descriptor, STDERR_FILENO);
    }
    ::execv(exe.c_str(), argv.data());
    // The job's log is the only channel left: the batch reports its first line (a binary replaced
    // while the batch runs, say). write() is async-signal-safe; strerror reads glibc's table.
    const char* reason = ::strerror(errno);
    for (const char* part : {"cannot start ", exe.c_str(), ": ", reason, "\n"})
      if (::write(STDERR_FILENO, part, std::strlen(part)) < 0) break;
    ::_exit(127);
  }
  int status = 0;
  bool timed_out = false;
  for (;;) {
    const pid_t done = ::waitpid(child, &status, WNOHANG);
    if (done == child) break;
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (elapsed > time_limit && !timed_out) {
      ::kill(child, SIGKILL);
      timed_out = true;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  Outcome outcome;
  outcome.name = job.name;
  outcome.body = job.body.stem().string();
  outcome.seconds = seconds;
  if (timed_out) {
    outcome.status = "timeout";
    outcome.message = "over " + std::to_string(static_cast<int>(time_limit)) + " s";
  } else if (WIFSIGNALED(status)) {
    outcome.status = "crash";
    outcome.message = std::string("signal ") + std::to_string(WTERMSIG(status));
  } else if (const int code = WEXITSTATUS(status);
             (code == 0 || code == 3) && std::filesystem::exists(report)) {
    outcome = read_outcome(job, report, code, seconds);
  } else {
    outcome.status = "error";
    std::ifstream in(log);
    std::getline(in, outcome.message);
    if (outcome.message.empty()) outcome.message = "exit code " + std::to_string(code);
  }
  nlohmann::json record{{"name", outcome.name},
                        {"body", outcome.body},
                        {"status", outcome.status},
                        {"seconds", outcome.seconds},
                        {"message", outcome.message}};
  write_file_atomically(files.outcome, record.dump() + "\n");
  return outcome;
}

// A finished job from an earlier run of the same batch, or nothing.
std::optional<Outcome> previous_outcome(const Job& job, const std::filesystem::path& output) {
  const std::filesystem::path record = output / (job.name + ".outcome.json");
  if (!std::filesystem::exists(record)) return std::nullopt;
  const nlohmann::json json = nlohmann::json::parse(read_file(record), nullptr, false);
  if (json.is_discarded()) return std::nullopt;
  const std::string status = json.value("status", "");
  const double seconds = json.value("seconds", 0.0);
  const std::filesystem::path report = output / (job.name + ".report.json");
  if ((status == "ok" || status == "fails") && std::filesystem::exists(report))
    return read_outcome(job, report, status == "ok" ? 0 : 3, seconds);
  Outcome outcome;
  outcome.name = job.name;
  outcome.body = job.body.stem().string();
  outcome.status = status;
  outcome.seconds = seconds;
  outcome.message = json.value("message", "");
  return outcome;
}

// --shard K/N: 1 <= K <= N, whole numbers, nothing else in the word.
Shard parse_shard(const std::string& text) {
  Shard shard;
  const std::size_t slash = text.find('/');
  const auto whole = [&](std::size_t begin, std::size_t end, int& value) {
    const char* first = text.data() + begin;
    const char* last = text.data() + end;
    const auto [stop, error] = std::from_chars(first, last, value);
    return begin < end && error == std::errc() && stop == last;
  };
  if (slash == std::string::npos || !whole(0, slash, shard.index) ||
      !whole(slash + 1, text.size(), shard.count) || shard.count < 1 || shard.index < 1 ||
      shard.index > shard.count)
    throw UsageError("--shard K/N: K and N whole numbers, 1 <= K <= N (got '" + printable(text) +
                     "')");
  return shard;
}

}  // namespace

int batch_command(const std::vector<std::string>& args) {
  const CommandLine line(
      args, {},
      {"-o", "--jobs", "--body", "--bodies", "--time-limit", "--limit", "--parameters",
       "--attempts", "--export", "--clearance", "--shard", "--outfits"});
  const auto outfits = line.value("--outfits");
  if (outfits && !line.positional().empty())
    throw UsageError("a pattern folder or --outfits LIST, not both");
  const std::filesystem::path folder =
      outfits ? std::filesystem::path()
              : std::filesystem::path(line.only_positional("pattern folder"));
  const auto output_value = line.value("-o");
  if (!output_value) throw UsageError("-o OUTDIR is required");
  const std::filesystem::path output = *output_value;
  const int jobs =
      line.integer("--jobs", static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  const double time_limit = line.number("--time-limit", 300.0);
  const int limit = line.integer("--limit", 0);
  const std::string parameters =
      line.value("--parameters") ? std::filesystem::absolute(*line.value("--parameters")).string()
                                 : std::string();
  if (jobs < 1) throw UsageError("--jobs must be at least 1");
  const int attempts = line.integer("--attempts", RecoverySettings{}.attempts);
  if (attempts < 1) throw UsageError("--attempts must be 1 (a single pass) or more");
  std::optional<Shard> shard;
  if (const auto value = line.value("--shard")) shard = parse_shard(*value);
  // Checked here, before any job: each job's `run` gets the list as it is.
  const std::string export_list = line.value("--export").value_or("");
  std::vector<SewnExport> exports;
  if (line.has("--export")) try {
      exports = parse_sewn_exports(export_list);
    } catch (const std::invalid_argument& error) {
      throw UsageError(std::string("--export: ") + error.what());
    }
  // Checked here too, and passed to each job's `run` as it was given.
  const std::string clearance = line.value("--clearance").value_or("");
  if (line.has("--clearance")) {
    const double clearance_mm = line.number("--clearance", 0.0);
    if (!(clearance_mm >= 0.0 && clearance_mm <= 100.0))
      throw UsageError("--clearance must be between 0 and 100 (mm)");
  }
  if (!outfits && !std::filesystem::is_directory(folder))
    throw InputError(folder.string() + ": not a folder");

  const std::filesystem::path fallback_body = line.value("--body").value_or(default_body_path());
  std::vector<Job> all;
  if (outfits) {
    all = outfit_jobs(*outfits, fallback_body);
    if (limit > 0 && static_cast<int>(all.size()) > limit) all.resize(limit);
  }
  const std::map<std::string, std::string> index =
      outfits ? std::map<std::string, std::string>() : bodies_from_index(folder);
  const std::filesystem::path bodies =
      line.value("--bodies").value_or((folder / ".." / ".." / "bodies").string());
  for (const auto& pattern :
       outfits ? std::vector<std::filesystem::path>() : pattern_files(folder)) {
    Job job{{pattern}, fallback_body, pattern.stem().string()};
    if (const auto it = index.find(pattern.filename().string());
        it != index.end() && !line.has("--body")) {
      job.body = bodies / (it->second + ".obj");
      if (!std::filesystem::exists(job.body))
        throw InputError(folder.string() + "/index.json: body '" + printable(it->second) +
                         "' not found in " + bodies.string() + " (use --bodies DIR)");
    }
    all.push_back(job);
    if (limit > 0 && static_cast<int>(all.size()) >= limit) break;
  }
  if (all.empty())
    throw InputError(outfits ? *outfits + ": no outfit" : folder.string() + ": no pattern files");
  // Round robin over the name-sorted list rather than contiguous blocks: neighbouring patterns of
  // a dataset tend to be alike (gc_0000..), so each shard gets a similar mix and a similar time.
  // A shard may be empty (more shards than patterns): it writes an empty summary, so that the
  // merge of a job array still finds every shard.
  if (shard) {
    shard->patterns = static_cast<int>(all.size());
    std::vector<Job> mine;
    for (auto i = static_cast<std::size_t>(shard->index - 1); i < all.size();
         i += static_cast<std::size_t>(shard->count))
      mine.push_back(all[i]);
    all = std::move(mine);
  }
  // The output folder may not be the pattern folder or inside it: its reports are .json files,
  // read back as patterns by the next run of the batch.
  OutputPlan plan;
  if (outfits)
    plan.input("--outfits", *outfits);
  else
    plan.input_folder("DIR", folder);
  if (!parameters.empty()) plan.input("--parameters", parameters);
  plan.output_folder("-o", output);
  for (const Job& job : all) {
    if (outfits)
      for (const std::filesystem::path& pattern : job.patterns)
        plan.input(job.name + "'s pattern", pattern);
    plan.input(job.name + "'s body", job.body);
    plan.input(job.name + "'s body locations", location_overrides_path(job.body));
    const JobFiles files = job_files(job, output);
    for (const std::filesystem::path& file : {files.obj, files.report, files.log, files.outcome})
      plan.output("-o", file);
    for (SewnExport kind : exports)
      plan.output("--export", sewn_export_path(files.obj, kind));
  }
  plan.output("-o", output / "summary.md");
  plan.output("-o", output / "summary.json");
  plan.check();
  std::filesystem::create_directories(output);

  const auto start = std::chrono::steady_clock::now();
  std::vector<Outcome> outcomes(all.size());
  std::vector<std::size_t> pending;
  for (std::size_t i = 0; i < all.size(); ++i) {
    if (auto previous = previous_outcome(all[i], output))
      outcomes[i] = *previous;
    else
      pending.push_back(i);
  }
  const bool terminal = ::isatty(STDOUT_FILENO);
  if (shard)
    std::printf("shard %d/%d of %d patterns: ", shard->index, shard->count, shard->patterns);
  std::printf("%zu patterns, %zu already done, %d jobs\n", all.size(), all.size() - pending.size(),
              jobs);
  std::atomic<std::size_t> next{0}, finished{0};
  std::mutex print;
  const auto worker = [&] {
    for (std::size_t k = next++; k < pending.size(); k = next++) {
      const std::size_t i = pending[k];
      outcomes[i] = run_job(all[i], output, time_limit, parameters, std::to_string(attempts),
                            export_list, clearance);
      const std::size_t count = ++finished;
      std::lock_guard<std::mutex> lock(print);
      if (terminal) {
        const int width = 30, filled = static_cast<int>(width * count / pending.size());
        std::printf("\r[%s%s] %zu/%zu %-24s %-7s", std::string(filled, '#').c_str(),
                    std::string(width - filled, '.').c_str(), count, pending.size(),
                    all[i].name.c_str(), outcomes[i].status.c_str());
        std::fflush(stdout);
      }
    }
  };
  std::vector<std::thread> threads;
  for (int j = 0; j < jobs; ++j)
    threads.emplace_back(worker);
  for (auto& thread : threads)
    thread.join();
  if (terminal) std::printf("\n");
  write_batch_summary(
      outcomes, output,
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), shard);
  return kSuccess;
}

}  // namespace garment::cli
