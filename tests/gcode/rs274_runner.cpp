#include "gcode/rs274_runner.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

extern char** environ;

namespace cutcalc::test::gcode {

namespace {

bool write_file(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out << text;
  return static_cast<bool>(out);
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

std::string temp_root() {
  const char* tmp = std::getenv("TMPDIR");
  return (tmp != nullptr && *tmp != '\0') ? std::string(tmp) : std::string("/tmp");
}

// Removes the files this runner wrote and the directory itself.
class TempDir {
 public:
  TempDir() {
    std::string pattern = temp_root() + "/cutcalc-rs274-XXXXXX";
    std::vector<char> buffer(pattern.begin(), pattern.end());
    buffer.push_back('\0');
    if (::mkdtemp(buffer.data()) != nullptr) path_ = buffer.data();
  }
  ~TempDir() {
    if (path_.empty()) return;
    for (const char* name : {"FILE.ngc", "strict.ini", "stdout.txt", "stderr.txt"}) {
      ::unlink((path_ + "/" + name).c_str());
    }
    ::rmdir(path_.c_str());
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
};

}  // namespace

std::string rs274_executable() {
#ifdef CUTCALC_RS274
  return CUTCALC_RS274;
#else
  return "rs274";
#endif
}

namespace {

Rs274Run run_in_temp_dir(const std::string& program_text, const std::string& executable,
                         int timeout_s, const std::string* tool_table) {
  Rs274Run run;
  const TempDir dir;
  if (dir.path().empty()) {
    run.spawn_error = "mkdtemp failed: " + std::string(std::strerror(errno));
    return run;
  }
  const std::string ngc = dir.path() + "/FILE.ngc";
  const std::string ini = dir.path() + "/strict.ini";
  const std::string out = dir.path() + "/stdout.txt";
  const std::string err = dir.path() + "/stderr.txt";
  const std::string tbl = dir.path() + "/tool.tbl";
  if (!write_file(ngc, program_text) || !write_file(ini, kStrictIni) ||
      (tool_table != nullptr && !write_file(tbl, *tool_table))) {
    run.spawn_error = "cannot write into " + dir.path();
    return run;
  }

  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 1, out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  posix_spawn_file_actions_addopen(&actions, 2, err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0600);
  // rs274 reads and writes its parameter file (rs274ngc.var) in the working directory: each run
  // gets its own, or parallel test processes race on one file.
  posix_spawn_file_actions_addchdir_np(&actions, dir.path().c_str());

  std::vector<std::string> args = {executable, "-i", ini};
  if (tool_table != nullptr) {
    args.emplace_back("-t");
    args.push_back(tbl);
  }
  args.emplace_back("-g");
  args.push_back(ngc);
  std::vector<char*> argv;
  for (auto& arg : args) argv.push_back(arg.data());
  argv.push_back(nullptr);

  // rs274 memory-maps $HOME/.tool.mmap and truncates it on start: two runs sharing a HOME kill
  // each other with SIGBUS (seen with ctest -j). Each run gets the temp dir as its HOME.
  std::vector<std::string> environment = {"HOME=" + dir.path()};
  for (char** entry = environ; *entry != nullptr; ++entry) {
    if (std::strncmp(*entry, "HOME=", 5) != 0) environment.emplace_back(*entry);
  }
  std::vector<char*> envp;
  for (auto& entry : environment) envp.push_back(entry.data());
  envp.push_back(nullptr);

  pid_t pid = 0;
  const int spawn_status =
      posix_spawnp(&pid, executable.c_str(), &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  if (spawn_status != 0) {
    run.spawn_error = "cannot run '" + executable + "': " + std::strerror(spawn_status) +
                      " (install it: apt-get install -y --no-install-recommends linuxcnc-uspace)";
    return run;
  }
  run.started = true;

  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(timeout_s);
  int status = 0;
  for (;;) {
    const pid_t done = ::waitpid(pid, &status, WNOHANG);
    if (done == pid) break;
    if (done < 0 && errno != EINTR) {
      run.spawn_error = "waitpid failed: " + std::string(std::strerror(errno));
      return run;
    }
    if (std::chrono::steady_clock::now() > deadline) {
      ::kill(pid, SIGKILL);
      ::waitpid(pid, &status, 0);
      run.timed_out = true;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (WIFEXITED(status)) {
    run.exit_code = WEXITSTATUS(status);
  } else if (WIFSIGNALED(status)) {
    run.exit_code = 128 + WTERMSIG(status);
  }
  run.output = read_file(out);
  run.errors = read_file(err);
  return run;
}

}  // namespace

Rs274Run run_rs274(const std::string& program_text, const std::string& executable, int timeout_s) {
  return run_in_temp_dir(program_text, executable, timeout_s, nullptr);
}

Rs274Run run_rs274_with_tools(const std::string& program_text, const std::string& tool_table) {
  return run_in_temp_dir(program_text, rs274_executable(), 120, &tool_table);
}

}  // namespace cutcalc::test::gcode
