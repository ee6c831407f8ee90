#pragma once
// Typed exceptions of the library. The command line maps them to exit codes: UsageError
// to 2, everything else to 1. Messages are one line, without a trailing period.
#include <stdexcept>
#include <string>

namespace prism {

class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The request itself is malformed (unknown name, out-of-range option).
class UsageError : public Error {
 public:
  using Error::Error;
};

// Reading or writing a file failed.
class IoError : public Error {
 public:
  using Error::Error;
};

// A scene description is malformed or refers to something that does not exist.
class SceneError : public Error {
 public:
  using Error::Error;
};

}  // namespace prism
