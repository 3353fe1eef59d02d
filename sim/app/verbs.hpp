#pragma once
/// The registry of the verbs whose options are declared (sim/app/options.hpp): a verb's
/// name, its one-line summary and its option list, read by both front ends (the command
/// line's help, Python's signatures and docstrings) and by the test that holds them to
/// each other. A new verb adds its options struct and one line here.

#include <functional>
#include <string>
#include <vector>

#include "sim/app/options.hpp"

namespace mmv::app {

struct VerbDeclaration {
  std::string name;     ///< "modes": the command and the Python function (with '_' for '-')
  std::string summary;  ///< the command's one-line description
  std::string outputs;  ///< the files `--out DIR` receives, as --help lists them
  std::function<std::vector<OptionDescription>()> options;
};

template <class Options>
VerbDeclaration declareVerb(std::string name, std::string summary, std::string outputs) {
  return {std::move(name), std::move(summary), std::move(outputs), &describeOptions<Options>};
}

/// Every declared verb, in the order `mmvlab --help` lists them.
const std::vector<VerbDeclaration>& declaredVerbs();
/// The verb named `name`; std::out_of_range for one not declared.
const VerbDeclaration& declaredVerb(const std::string& name);

/// The option the command line spells `cli_flag`, as `front` spells it: a declared
/// option's key where a declared verb has that flag ("--topology" -> "topologies"), else
/// `optionName`'s. For the messages of `OptionError`s, raised below the studies.
std::string declaredOptionName(Front front, const std::string& cli_flag);

}  // namespace mmv::app
