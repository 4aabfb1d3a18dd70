// Runs a program (the built strata-sim) in a child process, as a user would from a shell, and
// collects its exit status and everything it printed (stdout and stderr, interleaved).
// `file_size_limit` (bytes, 0: none) sets RLIMIT_FSIZE in the child with SIGXFSZ ignored, so a
// write beyond it fails with EFBIG as a full disk would fail with ENOSPC. A child that runs
// longer than `timeout_seconds` is killed by SIGALRM (a hang fails the test, not the suite).
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdint>
#include <string>
#include <vector>

namespace strata::sim::testing {

struct ProgramResult {
  int exit_status = -1;  // -1 if it ended by a signal
  int signal = 0;
  std::string output;
  bool ok() const { return exit_status == 0; }
};

// As run_program, and sends `signo` to the child once `trigger` appears in its output (at
// most once); `*sent` says whether it was sent.
inline ProgramResult run_program_signalled(const std::vector<std::string>& args, const std::string& trigger,
                                           int signo, bool* sent, uint64_t file_size_limit = 0,
                                           unsigned timeout_seconds = 120) {
  int out[2];
  ProgramResult r;
  *sent = false;
  if (pipe(out) != 0) return r;
  const pid_t pid = fork();
  if (pid < 0) return r;
  if (pid == 0) {
    dup2(out[1], STDOUT_FILENO);
    dup2(out[1], STDERR_FILENO);
    close(out[0]);
    if (file_size_limit > 0) {
      signal(SIGXFSZ, SIG_IGN);
      const rlimit lim{file_size_limit, file_size_limit};
      setrlimit(RLIMIT_FSIZE, &lim);
    }
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    setenv("SC_COPYRIGHT_MESSAGE", "DISABLE", 1);
    alarm(timeout_seconds);  // survives the exec
    execv(argv[0], argv.data());
    _exit(127);
  }
  close(out[1]);
  char buf[4096];
  for (ssize_t n; (n = read(out[0], buf, sizeof buf)) > 0;) {
    r.output.append(buf, static_cast<size_t>(n));
    if (!*sent && !trigger.empty() && r.output.find(trigger) != std::string::npos) {
      kill(pid, signo);
      *sent = true;
    }
  }
  close(out[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  if (WIFEXITED(status)) r.exit_status = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  return r;
}

inline ProgramResult run_program(const std::vector<std::string>& args, uint64_t file_size_limit = 0,
                                 unsigned timeout_seconds = 120) {
  bool sent = false;
  return run_program_signalled(args, "", 0, &sent, file_size_limit, timeout_seconds);
}

}  // namespace strata::sim::testing
