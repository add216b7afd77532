#include "oracle.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>
#include <sstream>

#include "cli.hpp"

namespace bounce::fuzz {

namespace {

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

// Words of printed text: runs of the characters a number or a name is made of.
std::set<std::string> words_of(std::string_view text) {
  auto part_of_word = [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.' ||
           c == '+' || c == '-';
  };
  std::set<std::string> words;
  std::size_t i = 0;
  while (i < text.size()) {
    if (!part_of_word(text[i])) {
      ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && part_of_word(text[j])) ++j;
    words.emplace(text.substr(i, j - i));
    i = j;
  }
  return words;
}

// A non-finite number as fmt and iostreams print it ("nan", "-inf"; the C header's NAN
// macro and the help's words are not numbers), unless the user's own text holds that word.
std::string non_finite_word(std::string_view text, const std::set<std::string>& echoed) {
  static const std::set<std::string> non_finite = {"nan", "-nan", "+nan", "inf", "-inf", "+inf"};
  for (const std::string& w : words_of(text)) {
    if (non_finite.contains(w) && !echoed.contains(w)) return w;
  }
  return {};
}

// Lines beside the result: a validity warning, or progress ("bounce curve: 3/10 (30%) 1.2 s").
bool is_side_line(const std::string& line) {
  if (line.starts_with("bounce: warning: ")) return true;
  return line.starts_with("bounce ") && line.find(": ") != std::string::npos && line.find('/') != std::string::npos &&
         line.find("%) ") != std::string::npos;
}

std::string report(const std::vector<std::string>& args, const CliResult& r, const std::string& what) {
  return what + "\n  command: " + command_line(args) + "\n  exit code: " + std::to_string(r.code) +
         "\n  stdout (first 600 bytes): " + r.out.substr(0, 600) + "\n  stderr (first 600 bytes): " + r.err.substr(0, 600);
}

}  // namespace

void finding(const std::string& what) {
  std::fprintf(stderr, "\nFINDING: %s\n", what.c_str());
  std::fflush(stderr);
  std::abort();
}

std::string command_line(const std::vector<std::string>& args) {
  std::string line = "bounce";
  for (const std::string& a : args) {
    const bool plain = !a.empty() && a.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789"
                                                         "-_.:,=+/@") == std::string::npos;
    if (plain) {
      line += " " + a;
      continue;
    }
    line += " '";
    for (char c : a) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += "'";
  }
  return line;
}

CliResult run_cli(const std::vector<std::string>& args, const std::string& input) {
  std::vector<const char*> argv{"bounce"};
  for (const std::string& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  std::istringstream in(input);
  std::streambuf* const old_out = std::cout.rdbuf(out.rdbuf());
  std::streambuf* const old_err = std::cerr.rdbuf(err.rdbuf());
  std::streambuf* const old_in = std::cin.rdbuf(in.rdbuf());
  std::cout.clear();
  std::cerr.clear();
  std::cin.clear();
  CliResult r;
  try {
    r.code = cli::run(static_cast<int>(argv.size()), argv.data());
  } catch (const std::exception& e) {
    std::cout.rdbuf(old_out);
    std::cerr.rdbuf(old_err);
    std::cin.rdbuf(old_in);
    finding("an exception escaped bounce::cli::run (the CLI would terminate): " + std::string(e.what()) +
            "\n  command: " + command_line(args));
  }
  std::cout.rdbuf(old_out);
  std::cerr.rdbuf(old_err);
  std::cin.rdbuf(old_in);
  std::cout.clear();
  std::cin.clear();
  r.out = out.str();
  r.err = err.str();
  return r;
}

void check_cli(const std::vector<std::string>& args, const CliResult& r, const std::string& echoed_text) {
  std::string user_text = echoed_text;
  for (const std::string& a : args) user_text += "\n" + a;
  const std::set<std::string> echoed = words_of(user_text);

  if (r.code != 0 && r.code != 2 && r.code != 3) {
    finding(report(args, r, "exit code " + std::to_string(r.code) + " (docs/cli.md: 0, 2 or 3; 4 is an internal error)"));
  }
  // --help and `bounce models` print the declarations' words ("inf for a flat direction").
  const bool words = r.out.starts_with("Usage: ") || r.out.find("\nUsage: ") != std::string::npos ||
                     (!args.empty() && args.front() == "models");
  if (!words) {
    if (const std::string w = non_finite_word(r.out, echoed); !w.empty()) {
      finding(report(args, r, "stdout prints a number as '" + w + "' (docs/cli.md: never a NaN or an infinity)"));
    }
  }
  if (r.code == 0) return;

  std::vector<std::string> messages;
  for (const std::string& line : lines_of(r.err)) {
    if (!is_side_line(line)) messages.push_back(line);
  }
  if (messages.size() != 1 || r.err.empty() || r.err.back() != '\n') {
    finding(report(args, r, "exit " + std::to_string(r.code) + " without exactly one line on stderr (docs/cli.md)"));
  }
  const std::string& message = messages.front();
  if (r.code == 2) {
    if (!r.out.empty()) finding(report(args, r, "exit 2 (bad input) with output on stdout"));
    if (!message.starts_with("bounce: error: ")) finding(report(args, r, "exit 2 without 'bounce: error: '"));
    // The allowed range is the library's own words: a nan or inf there is a broken range.
    const auto expected = message.find(" is invalid: expected ");
    if (expected != std::string::npos) {
      if (const std::string w = non_finite_word(message.substr(expected), echoed); !w.empty()) {
        finding(report(args, r, "the allowed range of an error message holds '" + w + "'"));
      }
    }
  } else if (!message.starts_with("bounce: numerical error: ") &&
             !message.starts_with("bounce: error: could not write")) {
    finding(report(args, r, "exit 3 without 'bounce: numerical error: '"));
  }
}

std::string scratch_file(const std::string& name, std::string_view text) {
  // Never destroyed, so that the clean-up at exit can still read it.
  static const std::filesystem::path* const dir = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "bounce-fuzz-XXXXXX").string();
    if (::mkdtemp(pattern.data()) == nullptr) finding("cannot make a scratch directory");
    auto* made = new std::filesystem::path(pattern);
    std::atexit([] {
      std::error_code ignored;
      std::filesystem::remove_all(*dir, ignored);
    });
    return made;
  }();
  const std::filesystem::path path = *dir / name;
  std::ofstream(path, std::ios::binary | std::ios::trunc).write(text.data(), static_cast<std::streamsize>(text.size()));
  return path.string();
}

}  // namespace bounce::fuzz
