// Errors of zdg. Every exception zdg throws derives from zdg::Error; its message names the
// offending value (and, for files, the line). The command line turns an Error into one line
// on stderr and exit status 2.
#pragma once

#include <stdexcept>
#include <string>

namespace zdg {

/// Base of every zdg exception.
class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// An exact integer result does not fit the integer type that computed it. Algorithms run
/// "exact by escalation" catch it and re-run on a wider type (see arith/escalate.hpp).
class OverflowError : public Error {
public:
  using Error::Error;
};

/// A value given by the caller is outside the documented domain (a zero denominator, a
/// negative radius, a malformed number, ...).
class InvalidArgument : public Error {
public:
  using Error::Error;
};

/// A file could not be read or written, or its content is malformed.
class IoError : public Error {
public:
  using Error::Error;
};

} // namespace zdg
