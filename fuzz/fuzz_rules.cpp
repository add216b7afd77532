// Fuzz target: the encounters of `bounce rules` (JSON on standard input or --input F).
//
// Input: a first line choosing the pair and model (a digit, below), then the JSON
// encounters. Properties (docs/hardening.md): the CLI's contract (exit 0, 2 or 3, one line
// on stderr for an error, no nan/inf on stdout); no crash or sanitizer report in the JSON
// reading, the impulse of BSHP96 (42)-(43) or a model's collision at the encounter's speeds.
#include <cstdint>
#include <string>
#include <vector>

#include "oracle.hpp"

namespace {

// The pairs and models of the recorded calls (tests/golden/calls.txt) and a few more.
const std::vector<std::vector<std::string>>& setups() {
  static const std::vector<std::vector<std::string>> s = {
      {"--material", "ice-bshp96", "--radius", "0.01"},
      {"--material", "ice-bshp96", "--radius", "0.01", "--A", "1e-6", "--friction", "0.1", "--asperity", "1e-6"},
      {"--material", "water-ice", "--radius", "1e-6", "--model", "krijt", "--tvis", "1e-11"},
      {"--material", "steel", "--radius", "1e-3", "--wall", "--A", "1e-7", "--friction", "0.3", "--tangential-law",
       "step", "--shear-damping", "1e4"},
      {"--material", "water-ice", "--radius", "1e-6", "--material2", "quartz", "--radius2", "3e-6", "--model",
       "jkr-viscoelastic", "--tvis", "1e-11", "--inertia", "0.3"},
  };
  return s;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string input(reinterpret_cast<const char*>(data), size);
  const auto newline = input.find('\n');
  const std::string first = input.substr(0, newline);
  const std::string json = newline == std::string::npos ? std::string() : input.substr(newline + 1);
  // '0'-'4': setups()[0-4] with the JSON on standard input; '5'-'9': the same from --input F.
  const unsigned choice = first.empty() ? 0u : static_cast<unsigned>(static_cast<unsigned char>(first[0]) - '0') % 10u;

  std::vector<std::string> args = {"rules"};
  const auto& setup = setups()[choice % setups().size()];
  args.insert(args.end(), setup.begin(), setup.end());
  std::string stdin_text = json;
  if (choice >= setups().size()) {
    args.insert(args.end(), {"--input", bounce::fuzz::scratch_file("encounters.json", json)});
    stdin_text.clear();
  }
  bounce::fuzz::check_cli(args, bounce::fuzz::run_cli(args, stdin_text), json);
  return 0;
}
