// convexloc hostile tests — running the real `convexloc` binary on generated inputs and
// measuring it: exit status, stderr, stdout (kept or only summarised), peak memory, time.
#pragma once

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "scale.hpp"

namespace hostile {

namespace fs = std::filesystem;

// the peak resident memory of this process so far, in KiB
inline long peakKiB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

// the convexloc binary under test
inline const std::string kBin = CONVEXLOC_BIN;

// Sizes of the huge inputs are multiplied by CONVEXLOC_HOSTILE_SCALE (default 1), so that the
// sanitized run can use smaller ones; never below `floor`.
inline std::size_t scaled(std::size_t full, std::size_t floor) {
  return testscale::scaled(full, floor);
}

// How much a run's peak memory may exceed a small run's and still count as constant: 16 MiB.
// Under AddressSanitizer, freed blocks wait in its quarantine (256 MiB by default) before
// they are reused, so an allocation per query (GMP's temporaries in the rare exact
// fallback) raises the peak up to that much without any leak.
inline long constantMemorySlackKiB() {
#if defined(__SANITIZE_ADDRESS__)
  return (16 + 256) * 1024;
#else
  return 16 * 1024;
#endif
}

// A fresh directory under the system's temporary directory, removed with everything in it.
class TempDir {
 public:
  TempDir() {
    std::string pattern = (fs::temp_directory_path() / "convexloc-hostile-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  fs::path path_;
};

// writes `text` to `path`
inline void writeFile(const std::string& path, std::string_view text) {
  std::ofstream out(path, std::ios::binary);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!out) throw std::runtime_error("cannot write " + path);
}

// Writes a big file through a buffer: `fill` appends to the buffer until it returns false.
inline void writeBig(const std::string& path, const std::function<bool(std::string&)>& fill) {
  std::FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) throw std::runtime_error("cannot create " + path);
  std::string buf;
  bool more = true;
  while (more) {
    buf.clear();
    while (more && buf.size() < (std::size_t{1} << 20)) more = fill(buf);
    if (std::fwrite(buf.data(), 1, buf.size(), f) != buf.size()) {
      std::fclose(f);
      throw std::runtime_error("cannot write " + path);
    }
  }
  if (std::fclose(f) != 0) throw std::runtime_error("cannot write " + path);
}

// What one run of the tool did.
struct ToolRun {
  int status = -1;                       // exit status, or 128 + signal
  std::string out;                       // stdout, when kept (see Options::keepOut)
  std::string err;                       // stderr
  std::size_t outBytes = 0;              // stdout length, kept or not
  std::size_t outLines = 0;              // '\n' in stdout
  std::array<std::size_t, 3> answers{};  // lines "inside", "boundary", "outside" in stdout
  long maxRssKiB = 0;                    // peak resident memory of the tool
  double seconds = 0;                    // wall time
  bool timedOut = false;                 // killed at the deadline
};

struct Options {
  std::string stdinPath;                        // file for stdin; empty: /dev/null
  std::function<bool(std::string&)> stdinFill;  // or: generated, appended chunk by chunk
  std::string stdoutPath;                       // send stdout to this file (not counted)
  bool keepOut = true;                          // keep stdout in ToolRun::out
  double timeoutSeconds = 600;                  // kill after this long
};

namespace detail {

// counts the answers in stdout as it streams by, whatever the chunking
struct AnswerCounter {
  std::string partial;
  void feed(std::string_view chunk, ToolRun& r) {
    std::size_t start = 0;
    for (std::size_t i = 0; i < chunk.size(); ++i) {
      if (chunk[i] != '\n') continue;
      std::string_view line = chunk.substr(start, i - start);
      if (!partial.empty()) {
        partial.append(line);
        line = partial;
      }
      if (line == "inside")
        ++r.answers[0];
      else if (line == "boundary")
        ++r.answers[1];
      else if (line == "outside")
        ++r.answers[2];
      ++r.outLines;
      partial.clear();
      start = i + 1;
    }
    partial.append(chunk.substr(start));
  }
};

}  // namespace detail

// Runs `convexloc args...` and waits for it, feeding stdin and draining stdout and stderr.
inline ToolRun runTool(const std::vector<std::string>& args, const Options& o = {}) {
  int outPipe[2], errPipe[2], inPipe[2] = {-1, -1};
  if (pipe(outPipe) != 0 || pipe(errPipe) != 0) throw std::runtime_error("pipe failed");
  if (o.stdinFill && pipe(inPipe) != 0) throw std::runtime_error("pipe failed");
  auto t0 = std::chrono::steady_clock::now();
  pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    int in = -1;
    if (o.stdinFill)
      in = inPipe[0];
    else
      in = open(o.stdinPath.empty() ? "/dev/null" : o.stdinPath.c_str(), O_RDONLY);
    if (in < 0) _exit(126);
    dup2(in, 0);
    if (!o.stdoutPath.empty()) {
      int out = open(o.stdoutPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (out < 0) _exit(126);
      dup2(out, outPipe[1]);
      close(out);
    }
    dup2(outPipe[1], 1);
    dup2(errPipe[1], 2);
    for (int fd : {outPipe[0], outPipe[1], errPipe[0], errPipe[1], inPipe[0], inPipe[1], in})
      if (fd > 2) close(fd);
    std::vector<char*> argv{const_cast<char*>(kBin.c_str())};
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(kBin.c_str(), argv.data());
    _exit(127);
  }
  close(outPipe[1]);
  close(errPipe[1]);
  if (o.stdinFill) {
    close(inPipe[0]);
    fcntl(inPipe[1], F_SETFL, O_NONBLOCK);
    signal(SIGPIPE, SIG_IGN);  // the tool may stop reading early (a bad line)
  }
  ToolRun r;
  detail::AnswerCounter counter;
  std::string pending;  // generated stdin not yet written
  std::size_t pendingAt = 0;
  bool moreIn = static_cast<bool>(o.stdinFill);
  int inFd = o.stdinFill ? inPipe[1] : -1;
  bool outOpen = true, errOpen = true;
  std::vector<char> buf(1 << 16);
  while (outOpen || errOpen) {
    double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (elapsed > o.timeoutSeconds && !r.timedOut) {
      r.timedOut = true;
      kill(pid, SIGKILL);
    }
    std::vector<pollfd> fds;
    if (outOpen) fds.push_back({outPipe[0], POLLIN, 0});
    if (errOpen) fds.push_back({errPipe[0], POLLIN, 0});
    if (inFd >= 0) fds.push_back({inFd, POLLOUT, 0});
    if (poll(fds.data(), fds.size(), 1000) < 0 && errno != EINTR) break;
    for (const pollfd& p : fds) {
      if (p.revents == 0) continue;
      if (p.fd == inFd) {
        if (pendingAt == pending.size()) {
          pending.clear();
          pendingAt = 0;
          while (moreIn && pending.size() < (std::size_t{1} << 20)) moreIn = o.stdinFill(pending);
        }
        ssize_t n = pending.empty()
                        ? 0
                        : write(inFd, pending.data() + pendingAt, pending.size() - pendingAt);
        if (n > 0) pendingAt += static_cast<std::size_t>(n);
        bool broken = n < 0 && errno != EAGAIN;
        if (broken || (!moreIn && pendingAt == pending.size())) {
          close(inFd);
          inFd = -1;
        }
        continue;
      }
      ssize_t n = read(p.fd, buf.data(), buf.size());
      if (n <= 0) {
        (p.fd == outPipe[0] ? outOpen : errOpen) = false;
        continue;
      }
      std::string_view chunk(buf.data(), static_cast<std::size_t>(n));
      if (p.fd == outPipe[0]) {
        r.outBytes += chunk.size();
        counter.feed(chunk, r);
        if (o.keepOut) r.out.append(chunk);
      } else if (r.err.size() < (std::size_t{1} << 20)) {
        r.err.append(chunk);
      }
    }
  }
  if (inFd >= 0) close(inFd);
  close(outPipe[0]);
  close(errPipe[0]);
  int status = 0;
  rusage usage{};
  wait4(pid, &status, 0, &usage);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.maxRssKiB = usage.ru_maxrss;
  r.status = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  return r;
}

}  // namespace hostile
