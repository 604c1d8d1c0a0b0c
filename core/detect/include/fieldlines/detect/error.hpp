#pragma once
#include <stdexcept>
#include <string>

namespace fieldlines {

// Every recoverable failure of the core (bad file, bad input, bad values) is an Error with a
// message meant for the user: it names the file or value and what was expected.
class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what) : std::runtime_error(what) {}
};

}  // namespace fieldlines
