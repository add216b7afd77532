#pragma once
// Typed errors of the bounce library.
//
// Every error caused by user input is an InvalidArgument that names the
// parameter, the value given and what is allowed, so that a front end (the CLI,
// Python) can print one line and exit with code 2 without a stack trace.

#include <stdexcept>
#include <string>

namespace bounce {

/// Base of every exception bounce throws on purpose.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Bad user input: a parameter outside its allowed range, an unknown name,
/// a malformed data file, a missing required value.
class InvalidArgument : public Error {
 public:
  /// `parameter`: how the user names it (e.g. "--nu2", "water-ice.density");
  /// `value`: what was given, as text ("-3", "(not given)");
  /// `allowed`: the allowed range or set, as a sentence fragment ("-1 < nu < 0.5").
  InvalidArgument(std::string parameter, std::string value, std::string allowed);

  const std::string& parameter() const noexcept { return parameter_; }
  const std::string& value() const noexcept { return value_; }
  const std::string& allowed() const noexcept { return allowed_; }

  /// A copy naming the parameter differently (e.g. a front end maps the
  /// library's field name "E" of body 2 to its option "--E2").
  InvalidArgument renamed(std::string parameter) const;

 private:
  std::string parameter_;
  std::string value_;
  std::string allowed_;
};

/// A numerical procedure could not finish: step or time budget exhausted,
/// root not bracketed, non-finite state. Not the user's fault as such, but
/// always reported rather than looped on or returned as NaN.
class NumericalError : public Error {
 public:
  using Error::Error;
};

/// A part of bounce's installation is missing or from another build (a module: core/module.hpp).
class InstallationError : public Error {
 public:
  using Error::Error;
};

}  // namespace bounce
