#include "engine/core/atomic_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <mutex>
#include <optional>
#include <random>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace garment {
namespace {

std::filesystem::path temporary_sibling(const std::filesystem::path& path) {
  std::random_device entropy;
  std::ostringstream suffix;
  suffix << ".tmp-" << ::getpid() << "-" << std::hex << entropy();
  std::filesystem::path temporary = path;
  temporary += suffix.str();
  return temporary;
}

[[noreturn]] void fail(const std::filesystem::path& path, const std::string& what) {
  throw std::runtime_error(path.string() + ": cannot write: " + what);
}

std::mutex protected_mutex;
std::vector<std::filesystem::path> protected_files;  // as given; compared by identity (inode)

void refuse_protected(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) return;
  const std::lock_guard lock(protected_mutex);
  for (const std::filesystem::path& input : protected_files)
    if (std::filesystem::equivalent(path, input, error))
      fail(path, "it is the input file " + input.string() +
                     ", which is never overwritten; choose another name");
}

// The signals a commit of several files holds back: the catchable ones that end a process.
constexpr std::array<int, 4> kDeferredSignals = {SIGINT, SIGTERM, SIGHUP, SIGQUIT};
std::atomic<int> deferred_signal{0};
std::mutex commit_mutex;

void defer_signal(int signal) {
  int none = 0;
  deferred_signal.compare_exchange_strong(none, signal);
}

// For its lifetime, catches kDeferredSignals process-wide (blocking them in one thread would not
// do: the kernel delivers a process's signal to any thread that does not block it, and the
// arrangement's worker threads do not); afterwards restores the previous dispositions and raises
// the first signal caught, which then acts as it would have.
class SignalDeferral {
 public:
  SignalDeferral() {
    struct sigaction action {};
    action.sa_handler = defer_signal;
    action.sa_flags = SA_RESTART;
    sigfillset(&action.sa_mask);
    for (std::size_t i = 0; i < kDeferredSignals.size(); ++i)
      ::sigaction(kDeferredSignals[i], &action, &previous_[i]);
  }
  SignalDeferral(const SignalDeferral&) = delete;
  SignalDeferral& operator=(const SignalDeferral&) = delete;
  ~SignalDeferral() {
    for (std::size_t i = 0; i < kDeferredSignals.size(); ++i)
      ::sigaction(kDeferredSignals[i], &previous_[i], nullptr);
    if (const int signal = deferred_signal.exchange(0)) ::raise(signal);
  }

 private:
  std::array<struct sigaction, kDeferredSignals.size()> previous_{};
};

}  // namespace

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  write_file_atomically(path,
                        [&](std::ostream& out) { out.write(contents.data(), contents.size()); });
}

void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(std::ostream&)>& write) {
  AtomicFileSet file;
  file.stage(path, write);
  file.commit();
}

AtomicFileSet::~AtomicFileSet() {
  for (const auto& file : staged_) {
    std::error_code ignored;
    std::filesystem::remove(file.second, ignored);
  }
}

void AtomicFileSet::stage(const std::filesystem::path& path, std::string_view contents) {
  stage(path, [&](std::ostream& out) { out.write(contents.data(), contents.size()); });
}

void AtomicFileSet::stage(const std::filesystem::path& path,
                          const std::function<void(std::ostream&)>& write) {
  if (path.empty()) fail(path, "empty file name");
  if (std::filesystem::is_directory(path)) fail(path, "it is a directory");
  refuse_protected(path);
  const std::filesystem::path temporary = temporary_sibling(path);
  try {
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out) fail(path, std::strerror(errno));
      write(out);
      out.flush();
      if (!out) fail(path, "write error");
    }
    // fsync so that a crash after the rename cannot leave an empty file behind.
    const int descriptor = ::open(temporary.c_str(), O_RDONLY);
    if (descriptor >= 0) {
      ::fsync(descriptor);
      ::close(descriptor);
    }
    staged_.emplace_back(path, temporary);
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw;
  }
}

void AtomicFileSet::commit() {
  // One rename is atomic by itself; between several, a signal would split the set. Commits are
  // serialised because each deferral saves and restores the process's dispositions.
  std::unique_lock lock(commit_mutex, std::defer_lock);
  std::optional<SignalDeferral> deferral;
  if (staged_.size() > 1) {
    lock.lock();
    deferral.emplace();
  }
  for (std::size_t i = 0; i < staged_.size(); ++i) {
    std::error_code error;
    std::filesystem::rename(staged_[i].second, staged_[i].first, error);
    if (error) {
      const std::filesystem::path failed = staged_[i].first;
      staged_.erase(staged_.begin(), staged_.begin() + static_cast<std::ptrdiff_t>(i));
      fail(failed, error.message());
    }
  }
  staged_.clear();
}

void protect_input_file(const std::filesystem::path& path) {
  const std::lock_guard lock(protected_mutex);
  std::error_code error;
  for (const std::filesystem::path& input : protected_files)
    if (input == path || std::filesystem::equivalent(path, input, error)) return;
  protected_files.push_back(path);
}

}  // namespace garment
