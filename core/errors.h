#pragma once
/// \file errors.h
/// \brief The error types every layer shares. Each maps to one failure class and exit code
/// (failures.h); a message names the file, field or object and the reason.
#include <stdexcept>
#include <string>

namespace beverloo {

/// A configuration error: names the field (a JSON path) and the reason. Exit code 2.
class ConfigError : public std::runtime_error {
 public:
  ConfigError(const std::string& field, const std::string& reason)
      : std::runtime_error(field + ": " + reason), field_(field) {}
  const std::string& field() const { return field_; }

 private:
  std::string field_;
};

/// A run that has become unphysical (NaN, escape, huge overlap). Exit code 3.
class InstabilityError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An input/output failure (unwritable directory, corrupt file). Exit code 4.
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace beverloo
