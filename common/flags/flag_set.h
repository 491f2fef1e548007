// FlagSet: a program's command-line flags, declared once each (name, typed
// value, help line), parsed from argv, and listed by --help.
//
//   FlagSet flags("Usage: locatord [flags]");
//   flags.Add("threads", flag::Count(&config.threads, 1, 256),
//             "threads that locate one large batch together");
//   Status parsed = flags.Parse(argc, argv);
//
// The command line: long flags only, as "--name=value" or "--name value"
// ("--te X0 Y0 X1 Y1" for a flag of several words); names are matched
// whole, never by prefix. A flag's value may start with '-' ("-0.5"), but
// a word naming a declared flag is never taken as a value: "--chunk
// --json" is "--chunk" without its value. A flag not declared repeatable
// may be given once. "--help" (or "-h") anywhere before "--" asks for the
// help; the rest of the line is then not parsed. Words that are not flags,
// and every word after "--", are positional: collected by
// AllowPositionals, an error otherwise.
//
// Errors are InvalidArgument, one wording for every program:
//   --threads 'two': must be a whole number from 1 to 256   (FlagError)
//   --threads needs a value (N)
//   --listen is given twice
//   --redact takes no value, not 'yes'
//   unknown flag --no-such-flag
//   unexpected argument 'stray'
//
// Ownership: the values point at destinations the caller owns, which must
// outlive Parse. Thread-safety: none; declare and parse on one thread.

#ifndef LOCATOR_COMMON_FLAGS_FLAG_SET_H_
#define LOCATOR_COMMON_FLAGS_FLAG_SET_H_

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "common/flags/flag_value.h"
#include "locator/status.h"

namespace locator {

class FlagSet {
 public:
  // `usage` opens the --help text (what the program is and how it is
  // called); the flag list follows it.
  explicit FlagSet(std::string usage);

  FlagSet(const FlagSet&) = delete;
  FlagSet& operator=(const FlagSet&) = delete;

  // Declares --<name>. A name declared twice is a programming error: the
  // process aborts naming it.
  void Add(std::string_view name, FlagValue value, std::string_view help);

  // Words that are not flags go to *out, in order, instead of being an
  // error.
  void AllowPositionals(std::vector<std::string>* out);

  // Parses `args` (without the program's name), storing each flag's value
  // as it is read. Stops at the first error (see above).
  Status Parse(const std::vector<std::string>& args);
  // The same for main's argc/argv; argv[0] is the program and is skipped.
  Status Parse(int argc, const char* const* argv);

  // Whether the last Parse saw --help or -h.
  bool help_requested() const { return help_requested_; }
  // Whether the last Parse saw --<name>.
  bool Given(std::string_view name) const;

  // The usage followed by every flag: "--name SHAPE", its help and its
  // default, wrapped to 80 columns, in declaration order.
  std::string Help() const;

 private:
  struct Flag {
    std::string name;
    FlagValue value;
    std::string help;
    size_t times_given = 0;
  };

  Flag* Find(std::string_view name);
  const Flag* Find(std::string_view name) const;
  // Whether `word` is "--<declared name>" or "--<declared name>=...".
  bool NamesAFlag(std::string_view word) const;
  // Reads the flag `word` starts, and its value words from args[*next]
  // on, advancing *next past them.
  Status ParseFlag(std::string_view word, const std::vector<std::string>& args,
                   size_t* next);

  const std::string usage_;
  std::vector<Flag> flags_;
  std::vector<std::string>* positionals_ = nullptr;
  bool help_requested_ = false;
};

// What main() does with a parse's outcome: prints "<program>: <error>"
// and "(see <program> --help)" to stderr and returns 2, prints `help` (the
// help asked for; empty: none was) to stdout and returns 0, or returns
// nullopt when the program should run.
std::optional<int> ExitCodeForFlags(std::string_view program,
                                    const Status& parsed,
                                    const std::string& help);

}  // namespace locator

#endif  // LOCATOR_COMMON_FLAGS_FLAG_SET_H_
