#pragma once
// The CLI's text output (without --json or --csv): the front door's Records in words.

#include <string>

#include "bounce/core/record.hpp"

namespace bounce::cli {

std::string collide_text(const Record& outcome);
std::string contact_text(const Record& state);
std::string analytic_text(const Record& forms);
std::string sticking_text(const Record& sticking, const std::string& model);
std::string materials_text(const Value& materials);
std::string table_value_text(const Record& value);
/// `bounce fit`: best values with their ranges, chi^2, and the comparison when there is one.
std::string fit_text(const Record& fit);
/// `bounce models`: each model, what it is and its options.
std::string models_text(const Value& registry);
/// `bounce models --markdown`: the tables of docs/models.md.
std::string models_markdown(const Value& registry);

}  // namespace bounce::cli
