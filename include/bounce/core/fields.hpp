#pragma once
// A parameter struct declared once: its field table. Each field pairs a ParameterSpec (name,
// unit, range, default, help: what --help, Python's keywords, the type stubs and the docs show)
// with the struct member its value goes to. The table generates the specs a registry row
// declares, and reads the values bind_parameters() checked into the struct, once, at the front
// door; below it the library takes the struct.
//
//   struct ViscousParameters { std::optional<double> dissipative_constant; ... };
//   const FieldTable<ViscousParameters> fields{
//       {catalogue::dissipative_constant(), &ViscousParameters::dissipative_constant}, ...};
//   fields.specs();      // the row's parameters
//   fields.read(bound);  // the struct
// A rule between fields that no single spec states ("one of A, eta1 and eta2, or T_vis") is
// declared with the table too: FieldTable{...}.with(ParameterRule{...}).

#include <functional>
#include <initializer_list>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bounce/core/error.hpp"
#include "bounce/core/parameters.hpp"

namespace bounce {

template <class S>
struct Field {
  /// Where the value goes: a number given or its default (none: required), a number that may
  /// be absent, or a word (a choice).
  Field(ParameterSpec s, double S::*member)
      : spec(std::move(s)), read([member, name = spec.name, spec = spec](S& out, const Parameters& bound) {
          const auto x = bound.real(name);
          if (!x) throw InvalidArgument(name, "(not given)", spec.range.describe(spec.what()));
          out.*member = *x;
        }) {}
  Field(ParameterSpec s, std::optional<double> S::*member)
      : spec(std::move(s)), read([member, name = spec.name](S& out, const Parameters& bound) {
          if (bound.given(name)) out.*member = bound.real(name);
        }) {}
  Field(ParameterSpec s, std::string S::*member)
      : spec(std::move(s)),
        read([member, name = spec.name](S& out, const Parameters& bound) { out.*member = bound.text(name); }) {}

  ParameterSpec spec;
  std::function<void(S&, const Parameters&)> read;
};

template <class S>
class FieldTable {
 public:
  FieldTable(std::initializer_list<Field<S>> fields) : fields_(fields) {}

  /// The table with a rule between its fields (ParameterRule: checked once, where a model is
  /// made from the bound values).
  FieldTable with(ParameterRule rule) const {
    FieldTable out = *this;
    out.rules_.push_back(std::move(rule));
    return out;
  }
  const std::vector<ParameterRule>& rules() const noexcept { return rules_; }

  /// The specs, in the table's order.
  std::vector<ParameterSpec> specs() const {
    std::vector<ParameterSpec> out;
    for (const Field<S>& f : fields_) out.push_back(f.spec);
    return out;
  }

  /// The struct of values bound against these specs (or more: a row's shared ones too): a
  /// number given or its default (none: InvalidArgument, "(not given)"), an optional one
  /// where given, a word given or its default.
  S read(const Parameters& bound) const {
    S s{};
    for (const Field<S>& f : fields_) f.read(s, bound);
    return s;
  }

  const std::vector<Field<S>>& fields() const noexcept { return fields_; }

 private:
  std::vector<Field<S>> fields_;
  std::vector<ParameterRule> rules_;
};

}  // namespace bounce
