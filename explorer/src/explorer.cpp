// The explorer's binding: bounce's front door for the browser, as a C ABI of JSON text
// (docs/explorer.md). The page hands over what the user typed, by parameter name, as the CLI
// does; the reply is the CLI's JSON for the same command, or its error line.
#include <emscripten/emscripten.h>

#include <functional>
#include <map>
#include <sstream>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "bounce/api/front_door.hpp"
#include "bounce/api/json.hpp"
#include "bounce/core/error.hpp"

namespace {

using bounce::Value;
namespace api = bounce::api;

// The reply of the last call, read by bounce_explorer_text() (one call at a time: the page's
// thread is the only caller).
std::string reply;

// The commands the page runs: each returns what `bounce COMMAND --json` prints.
const std::map<std::string, std::function<Value(const api::Inputs&)>, std::less<>>& commands() {
  static const std::map<std::string, std::function<Value(const api::Inputs&)>, std::less<>> table{
      {"collide", [](const api::Inputs& in) { return Value(api::collide(in)); }},
      {"curve", [](const api::Inputs& in) { return Value(api::curve(in)); }},
      {"sticking", [](const api::Inputs& in) { return Value(api::sticking(in)); }},
      {"materials", [](const api::Inputs& in) { return api::materials(in); }},
      {"models", [](const api::Inputs&) { return api::models(); }}};
  return table;
}

// The page's inputs, {"radius": "1e-6", "trajectory": true, ...}: text as typed (so that a
// message quotes it as typed), flags as booleans.
api::Inputs read_inputs(std::string_view text) {
  const nlohmann::json j = nlohmann::json::parse(text);
  api::Inputs in;
  for (const auto& [name, value] : j.items()) {
    if (value.is_boolean()) {
      in.emplace(name, value.get<bool>());
    } else if (value.is_string()) {
      in.emplace(name, value.get<std::string>());
    } else {
      throw bounce::InvalidArgument(name, value.dump(), "text as typed in the page or true/false");
    }
  }
  return in;
}

// The CLI's name of a parameter that is one of its options ("tvis" -> "--tvis").
std::string option_name(const std::string& parameter, std::string_view command) {
  for (const bounce::ParameterSpec& s : api::offered_parameters(command)) {
    if (s.name != parameter) continue;
    std::string out = "--" + parameter;
    for (char& c : out) c = c == '_' ? '-' : c;
    return out;
  }
  return parameter;
}

std::string error_reply(const std::string& parameter, const std::string& message) {
  return nlohmann::json{{"parameter", parameter}, {"message", message}}.dump();
}

// Runs one command under the CLI's error policy; returns its exit code (0, 2 bad input,
// 3 not computable, 4 a bug) and leaves the JSON or the error in `reply`.
int run(std::string_view command, std::string_view inputs_text) {
  api::Inputs inputs;
  try {
    inputs = read_inputs(inputs_text);
    const auto found = commands().find(command);
    if (found == commands().end()) throw bounce::InvalidArgument("command", std::string(command), "collide, curve, sticking, materials or models");
    const Value result = found->second(inputs);
    if (const std::string at = api::non_finite_at(result); !at.empty()) {
      throw bounce::NumericalError("result " + at + " is outside the range of double precision; refusing to print it");
    }
    std::ostringstream out;
    api::write_json(out, result);
    reply = out.str();
    return 0;
  } catch (const bounce::InvalidArgument& caught) {
    const bounce::InvalidArgument e = api::as_typed(caught, inputs);
    reply = error_reply(e.parameter(), e.renamed(option_name(e.parameter(), command)).what());
    return 2;
  } catch (const bounce::NumericalError& e) {
    reply = error_reply("", std::string("numerical error: ") + e.what());
    return 3;
  } catch (const nlohmann::json::exception& e) {
    reply = error_reply("", std::string("internal error: the page's inputs are not JSON: ") + e.what());
    return 4;
  } catch (const std::exception& e) {
    reply = error_reply("", std::string("internal error: ") + e.what());
    return 4;
  }
}

}  // namespace

extern "C" {

/// `command` with `inputs` (a JSON object of text): the exit code the CLI would give.
EMSCRIPTEN_KEEPALIVE int bounce_explorer_call(const char* command, const char* inputs) { return run(command, inputs); }

/// The last call's JSON: the result (as `bounce COMMAND --json` prints it) or
/// {"parameter": NAME, "message": the CLI's error line without "bounce: error: "}.
EMSCRIPTEN_KEEPALIVE const char* bounce_explorer_text() { return reply.c_str(); }

}
