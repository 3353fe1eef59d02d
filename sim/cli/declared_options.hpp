#pragma once
/// The command-line adapter of the declared options (sim/app/options.hpp): each field of
/// a verb's options struct becomes its CLI11 option or flag, with the help sentence, unit,
/// range and default the declaration gives (the same text Python's docstring shows). The
/// values are only parsed here: the study checks their ranges, once.

#include <optional>
#include <string>
#include <vector>

#include "sim/app/options.hpp"

namespace CLI {
class App;
}

namespace mmv::cli {

/// Adds one field's option to `cmd`: a flag for a bool (its negated flag sets it false),
/// an option for a number, a text or a list (commaSeparated: one value split at commas).
struct CliOptionAdder {
  CLI::App* cmd;
  void operator()(bool& v, const app::Option& o) const;
  void operator()(int& v, const app::Option& o) const;
  void operator()(double& v, const app::Option& o) const;
  void operator()(std::string& v, const app::Option& o) const;
  void operator()(std::vector<std::string>& v, const app::Option& o) const;
  void operator()(std::vector<int>& v, const app::Option& o) const;
  void operator()(std::vector<double>& v, const app::Option& o) const;
  void operator()(app::Band& v, const app::Option& o) const;
  void operator()(std::optional<double>& v, const app::Option& o) const;
  void operator()(std::optional<int>& v, const app::Option& o) const;
  void operator()(std::optional<std::string>& v, const app::Option& o) const;
};

/// Every declared option of `options` on `cmd`, in declaration order; `options` holds
/// its defaults when called (they are shown in the help) and receives the values parsed.
template <class Options>
void addDeclaredOptions(CLI::App* cmd, Options& options) {
  Options::fields(options, CliOptionAdder{cmd});
}

}  // namespace mmv::cli
