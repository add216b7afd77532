#pragma once
// Named parameters, declared once and checked in one place.
//
// Every input of bounce that a user types (a body property, a model constant, a numerical
// setting, what a command computes) is declared by a ParameterSpec: its name, kind, unit,
// allowed range and default. The name is the CLI option without its dashes, with '_' for
// '-' ("A", "contact_end", "power_d1"); Python takes the same names as keywords and LAMMPS's
// pair_coeff as keys. Front ends hand the library what the user typed, by name (text from a
// command line, numbers from Python); bind_parameters() checks every value against its spec and
// refuses a name that nothing declares, so an input is never silently ignored.

#include <limits>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace bounce {

/// A value as given: a number, a word (a choice, a name, a file), a list of numbers, or a flag.
using ParameterValue = std::variant<double, std::string, std::vector<double>, bool>;
/// What a user typed, by parameter name.
using ParameterInputs = std::map<std::string, ParameterValue, std::less<>>;

enum class ParameterKind {
  real,    ///< one number
  reals,   ///< `count` numbers ("R1,R2" on a command line)
  choice,  ///< one of `choices`
  text,    ///< free text (a material name, a file)
  flag,    ///< on or off
};

/// The allowed values of a real parameter: lo < x < hi, with either end included on
/// request; infinity only where `infinite` allows it (a flat direction has radius inf).
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_included = false;
  bool hi_included = false;
  bool infinite = false;
  bool integer = false;  ///< whole numbers only (counts)

  bool contains(double x) const;
  /// The allowed range as a sentence fragment about `what`: "A [s] >= 0 and finite",
  /// "0 < k < 1" (the wording of every bounce error message).
  std::string describe(std::string_view what) const;
};
/// x > 0 (finite), x >= 0 (finite), lo < x < hi.
Range positive();
Range non_negative();
Range open_interval(double lo, double hi);

/// How a parameter that can be fitted is gridded by default (analysis/fit.hpp): `points`
/// values spaced geometrically from lo to hi, in units of `scale`: "" for the SI unit,
/// "gamma_L" for the pair's surface energy from its materials, "E_soft" for the smaller
/// Young's modulus of the two bodies (the normalisations of K13 Fig 7).
struct FitGrid {
  double lo = 0.0;
  double hi = 0.0;
  std::size_t points = 0;
  std::string scale;
};

struct ParameterSpec {
  std::string name;      ///< "A", "contact_end", "power_d1" (the CLI option without dashes)
  ParameterKind kind = ParameterKind::real;
  std::string quantity;  ///< what it is, with its symbol: "dissipative constant A"
  std::string unit;      ///< SI unit ("s", "m", "Pa s"); empty when dimensionless
  std::string help;      ///< one line for --help, docstrings and docs (with its references)
  Range range;           ///< real and reals
  std::vector<std::string> choices;  ///< choice
  std::size_t count = 1;             ///< reals: how many numbers
  std::optional<ParameterValue> default_value;  ///< used when not given; none: optional or required
  std::string placeholder;  ///< how a value looks, for --help ("LO:HI:N", "FILE"); derived when empty
  std::optional<FitGrid> fit;  ///< a continuous physical parameter that `bounce fit` can fit, and its default grid

  /// "dissipative constant A [s]": the quantity and its unit, for messages.
  std::string what() const;
  /// The default as the user would type it ("0.02", "overlap"), or "" without one.
  std::string default_text() const;
};

// Specs in one expression (the declarations of the registries and commands).
ParameterSpec real_parameter(std::string name, std::string quantity, std::string unit, Range range, std::string help);
/// A choice; its default is the first choice.
ParameterSpec choice_parameter(std::string name, std::vector<std::string> choices, std::string help);
ParameterSpec text_parameter(std::string name, std::string help, std::string placeholder);
ParameterSpec flag_parameter(std::string name, std::string help);
ParameterSpec with_default(ParameterSpec spec, ParameterValue value);
ParameterSpec fittable(ParameterSpec spec, FitGrid grid);

/// Text of a value as the user would type it ("1e-06", "force", "0.001,0.005", "true").
std::string value_text(const ParameterValue& value);

/// Values checked against their specs (made by bind_parameters()).
class Parameters {
 public:
  Parameters() = default;

  /// True when the user gave a value (a default does not count).
  bool given(std::string_view name) const;
  /// The number given, else the default, else none.
  std::optional<double> real(std::string_view name) const;
  /// The number given or its default; InvalidArgument(name, "(not given)", why) without both.
  double require_real(std::string_view name, std::string_view why) const;
  /// The numbers given (reals), else none.
  std::optional<std::vector<double>> reals(std::string_view name) const;
  /// The choice or text given, else the default, else "".
  std::string text(std::string_view name) const;
  /// The flag (false unless given as true).
  bool flag(std::string_view name) const;

  /// Sets a number the caller has checked already (a fit's trial, inside its checked grid), as
  /// if given: no text is read. The spec must declare `name` a real and its range hold `value`
  /// (std::logic_error otherwise: a caller's bug, not a user's input).
  void set(std::string_view name, double value);

  /// Every value given, validated and converted (text read as numbers where declared so).
  const ParameterInputs& values() const noexcept { return values_; }
  /// A value as the user typed it (for messages: "1e-3", not "0.001"); "" if not given.
  std::string typed(std::string_view name) const;
  /// InvalidArgument for the first of `names` the user gave, "NAME = VALUE is invalid:
  /// expected <why>": an input the chosen model, law or command does not use.
  void refuse_given(std::span<const char* const> names, std::string_view why) const;
  /// The specs these values were checked against.
  const std::vector<ParameterSpec>& specs() const noexcept { return specs_; }
  const ParameterSpec* spec(std::string_view name) const;

 private:
  friend Parameters bind_parameters(std::span<const ParameterSpec>, const ParameterInputs&, std::string_view);
  std::vector<ParameterSpec> specs_;
  ParameterInputs values_;
  ParameterInputs typed_;  // as given, before conversion
};

/// A constraint between parameters that no single spec states ("one of A, eta1 and eta2, or
/// T_vis", "krijt needs T_vis"): which of its alternatives, each a set of parameters given
/// together, may or must be given. Declared beside a parameter table (FieldTable::with) and
/// checked once, where a model is made from its bound values.
struct ParameterRule {
  std::vector<std::vector<std::string>> alternatives;
  bool exclusive = true;  ///< at most one alternative given
  bool required = true;   ///< at least one given
  std::string expected;   ///< what a refusal expects: "one of A, the viscosities eta1 and eta2, or T_vis"

  /// InvalidArgument "NAME = VALUE is invalid: expected ..." for the first parameter that breaks
  /// it, `owner` ("model viscoelastic") added: one of an alternative given without the others,
  /// a second alternative (exclusive), or none (required; named by the first alternative's).
  void check(const Parameters& p, std::string_view owner) const;
};

/// Checks every input against the spec of its name: its kind (text is read as a number,
/// "R1,R2" as numbers, "inf" where allowed), its range or choices. A name without a spec
/// is an InvalidArgument naming it and listing what `owner` ("model viscoelastic",
/// "command contact") takes.
Parameters bind_parameters(std::span<const ParameterSpec> specs, const ParameterInputs& inputs, std::string_view owner);

/// A real number from text, InvalidArgument(name, text, "a number") otherwise (std::from_chars:
/// the whole text, no spaces; "inf" only with `infinite`).
double parse_real(std::string_view name, std::string_view text, bool infinite = false);

/// Specs by name across several lists (the first of each name), for listings and help.
std::vector<ParameterSpec> merge_specs(std::initializer_list<std::span<const ParameterSpec>> lists);

}  // namespace bounce
