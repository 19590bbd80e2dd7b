// Judging what an entry's body threw: the expected vern::Error kinds are
// the contract's answer to bad input; anything else is a finding.
#pragma once

#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>

#include "base/error.hpp"

namespace vern::fuzz {

// "Input", "Limit", ...: for findings.
std::string_view kind_name(ErrorKind kind);

// Runs `body` (which returns "" or a finding). A vern::Error whose kind is
// in `expected` and whose message starts with `where` (the file name the
// input was given, so the user learns where the problem is) ends the run
// without a finding; every other exception is described as a finding.
std::string judged(const std::function<std::string()>& body, std::initializer_list<ErrorKind> expected,
                   std::string_view where);

// The first `limit` bytes of a text, for findings that quote an input.
std::string excerpt(std::string_view text, std::size_t limit = 2000);

}  // namespace vern::fuzz
