// `bounce fit --plot FILE` (plot.hpp). Drawing stays in Python (bounce.plot, matplotlib) so that
// the CLI's figure is the one `bounce.plot.fit_curve` draws; the CLI runs
// `/usr/bin/python3 -m bounce.fit_figure FILE` with the fit's JSON on its standard input.
#include "plot.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "bounce/core/error.hpp"

extern char** environ;

namespace bounce::cli {

namespace {

namespace fs = std::filesystem;

constexpr const char* python = "/usr/bin/python3";  // Debian's, with python3-matplotlib

// The bounce package beside this executable: the build tree's python/ (build/bin/bounce) or
// the installed lib/python3/dist-packages (PREFIX/bin/bounce), then any PYTHONPATH given.
std::string python_path() {
  std::error_code error;
  const fs::path bin = fs::read_symlink("/proc/self/exe", error).parent_path();
  std::string out;
  for (const fs::path& dir : {bin / ".." / "python", bin / ".." / "lib" / "python3" / "dist-packages"}) {
    if (!error && fs::exists(dir / "bounce" / "__init__.py", error)) out += (out.empty() ? "" : ":") + dir.string();
  }
  if (const char* given = std::getenv("PYTHONPATH"); given != nullptr && *given != '\0') {
    out += (out.empty() ? "" : ":") + std::string(given);
  }
  return out;
}

// A file of our own in the temporary directory, removed with its owner.
struct TemporaryFile {
  std::string path;
  explicit TemporaryFile(const std::string& text) {
    const char* dir = std::getenv("TMPDIR");
    std::string name = std::string(dir != nullptr && *dir != '\0' ? dir : "/tmp") + "/bounce-plot-XXXXXX";
    const int fd = mkstemp(name.data());
    if (fd < 0) throw InvalidArgument("plot", "(a temporary file)", "a writable temporary directory ($TMPDIR or /tmp)");
    path = name;
    const bool written = ::write(fd, text.data(), text.size()) == static_cast<ssize_t>(text.size());
    ::close(fd);
    if (!written) throw InvalidArgument("plot", "(a temporary file)", "a writable temporary directory ($TMPDIR or /tmp)");
  }
  ~TemporaryFile() { ::unlink(path.c_str()); }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
};

// Runs python -m bounce.fit_figure ARGS with `input` on stdin; its exit status and the last
// line it wrote on stderr (the reason when it failed).
std::pair<int, std::string> run_figure(const std::vector<std::string>& args, const std::string& input) {
  const TemporaryFile in(input), err("");
  std::vector<std::string> words = {python, "-m", "bounce.fit_figure"};
  words.insert(words.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  std::vector<std::string> env = {"PYTHONPATH=" + python_path(), "MPLBACKEND=Agg"};
  for (char** e = environ; *e != nullptr; ++e) {
    const std::string var = *e;
    if (var.rfind("PYTHONPATH=", 0) != 0 && var.rfind("MPLBACKEND=", 0) != 0) env.push_back(var);
  }
  std::vector<char*> envp;
  for (std::string& e : env) envp.push_back(e.data());
  envp.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 0, in.path.c_str(), O_RDONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, err.path.c_str(), O_WRONLY | O_TRUNC, 0);
  pid_t pid = 0;
  const int spawned = posix_spawn(&pid, python, &actions, nullptr, argv.data(), envp.data());
  posix_spawn_file_actions_destroy(&actions);
  int status = 0;
  if (spawned != 0 || waitpid(pid, &status, 0) < 0) return {127, std::string(python) + " could not be started"};
  std::ifstream stream(err.path);
  std::string line, last;
  while (std::getline(stream, line)) {
    if (!line.empty()) last = line;
  }
  return {WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status), last};
}

}  // namespace

void check_plot(const std::string& file) {
  std::string extension = fs::path(file).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(), [](unsigned char c) { return std::tolower(c); });
  if (extension != ".png" && extension != ".svg" && extension != ".pdf") {
    throw InvalidArgument("plot", file, "a file name ending in .png, .svg or .pdf (the figure's format)");
  }
  const auto [status, reason] = run_figure({"--check", file}, "");
  if (status != 0) {
    throw InvalidArgument("plot", file,
                          "a machine where " + std::string(python) +
                              " draws it with matplotlib and the bounce package (apt install python3-matplotlib; "
                              "write --json and use bounce.plot.fit_curve elsewhere), but " +
                              (reason.empty() ? "it failed" : "it said: " + reason));
  }
}

void write_plot(const std::string& file, const std::string& fit_json) {
  const auto [status, reason] = run_figure({file}, fit_json);
  if (status != 0) {
    throw InvalidArgument("plot", file, "a file the figure can be written to, but " + std::string(python) +
                                            (reason.empty() ? " failed" : " said: " + reason));
  }
}

}  // namespace bounce::cli
