#include "sim/cli/declared_options.hpp"

#include <CLI/CLI.hpp>

#include "sim/app/study.hpp"
#include "sim/core/text.hpp"

namespace mmv::cli {

namespace {

/// The declaration's help text with the default the field holds now.
template <class T>
std::string help(const T& v, const app::Option& o) {
  return o.helpText(app::defaultText(app::optionValueJson(v), app::OptionType<T>::name));
}

/// What every option shares: required or not.
void finish(CLI::Option* opt, const app::Option& o) {
  if (o.isRequired()) opt->required();
}

template <class T>
void addList(CLI::App* cmd, std::vector<T>& v, const app::Option& o) {
  CLI::Option* opt = cmd->add_option(o.cliFlag(), v, (o.isCommaSeparated() ? "Comma-separated: " : "Repeatable: ") + help(v, o));
  if (o.isCommaSeparated())
    opt->delimiter(',');
  else
    opt->allow_extra_args(false);  // one item per occurrence: a scene path after it is the scene
  finish(opt, o);
}

}  // namespace

void CliOptionAdder::operator()(bool& v, const app::Option& o) const {
  if (o.negatedFlag())
    cmd->add_flag_callback(o.cliFlag(), [&v] { v = false; }, o.negatedHelp());
  else
    cmd->add_flag(o.cliFlag(), v, o.helpText(""));  // a flag's default is its absence
}
void CliOptionAdder::operator()(int& v, const app::Option& o) const { finish(cmd->add_option(o.cliFlag(), v, help(v, o)), o); }
void CliOptionAdder::operator()(double& v, const app::Option& o) const { finish(cmd->add_option(o.cliFlag(), v, help(v, o)), o); }
void CliOptionAdder::operator()(std::string& v, const app::Option& o) const { finish(cmd->add_option(o.cliFlag(), v, help(v, o)), o); }
void CliOptionAdder::operator()(std::vector<std::string>& v, const app::Option& o) const { addList(cmd, v, o); }
void CliOptionAdder::operator()(std::vector<int>& v, const app::Option& o) const { addList(cmd, v, o); }
void CliOptionAdder::operator()(std::vector<double>& v, const app::Option& o) const { addList(cmd, v, o); }

void CliOptionAdder::operator()(app::Band& v, const app::Option& o) const {
  const std::string flag = o.cliFlag();
  cmd->add_option_function<std::string>(
         flag,
         [&v, flag](const std::string& text) {
           const std::vector<std::string> p = split(text, ':');
           const std::optional<double> lo = p.size() == 2 ? app::finiteNumber(p[0]) : std::nullopt;
           const std::optional<double> hi = p.size() == 2 ? app::finiteNumber(p[1]) : std::nullopt;
           if (!lo || !hi)
             throw CLI::ValidationError(flag, "expected F_MIN_HZ:F_MAX_HZ, e.g. 0.1:50 (got '" + printable(text) + "')");
           v = {*lo, *hi};
         },
         help(v, o))
      ->type_name("F_MIN:F_MAX");
  finish(cmd->get_option(flag), o);
}

/// An optional field: given, it holds the value; absent, the scene's setting holds.
template <class T>
void addOptional(CLI::App* cmd, std::optional<T>& v, const app::Option& o) {
  finish(cmd->add_option_function<T>(o.cliFlag(), [&v](const T& x) { v = x; }, help(v, o)), o);
}

void CliOptionAdder::operator()(std::optional<double>& v, const app::Option& o) const { addOptional(cmd, v, o); }
void CliOptionAdder::operator()(std::optional<int>& v, const app::Option& o) const { addOptional(cmd, v, o); }
void CliOptionAdder::operator()(std::optional<std::string>& v, const app::Option& o) const { addOptional(cmd, v, o); }

}  // namespace mmv::cli
