#include "common/flags/flag_set.h"

#include <cstdlib>
#include <iostream>
#include <utility>

namespace locator {
namespace {

constexpr size_t kHelpWidth = 80;
// Where the help lines start, after "  --name SHAPE".
constexpr size_t kHelpColumn = 30;

bool IsHelp(std::string_view word) { return word == "--help" || word == "-h"; }

// The name in "--name" or "--name=value".
std::string_view FlagName(std::string_view word) {
  return word.substr(2, word.find('=') - 2);
}

// Appends `text` to *out in lines of at most kHelpWidth columns, each
// after kHelpColumn spaces but the first, which continues *out's last line.
void AppendWrapped(std::string_view text, std::string* out) {
  size_t column = kHelpColumn;
  bool line_start = true;
  while (!text.empty()) {
    const size_t space = text.find(' ');
    const std::string_view word = text.substr(0, space);
    text = space == std::string_view::npos ? "" : text.substr(space + 1);
    if (!line_start && column + 1 + word.size() > kHelpWidth) {
      *out += "\n" + std::string(kHelpColumn, ' ');
      column = kHelpColumn;
      line_start = true;
    }
    if (!line_start) {
      *out += ' ';
      ++column;
    }
    *out += word;
    column += word.size();
    line_start = false;
  }
}

}  // namespace

FlagSet::FlagSet(std::string usage) : usage_(std::move(usage)) {}

void FlagSet::Add(std::string_view name, FlagValue value,
                  std::string_view help) {
  if (Find(name) != nullptr || name == "help") {
    std::cerr << "FlagSet: --" << name << " declared twice" << std::endl;
    std::abort();
  }
  flags_.push_back(Flag{.name = std::string(name),
                        .value = std::move(value),
                        .help = std::string(help)});
}

void FlagSet::AllowPositionals(std::vector<std::string>* out) {
  positionals_ = out;
}

FlagSet::Flag* FlagSet::Find(std::string_view name) {
  for (Flag& flag : flags_) {
    if (flag.name == name) return &flag;
  }
  return nullptr;
}

const FlagSet::Flag* FlagSet::Find(std::string_view name) const {
  return const_cast<FlagSet*>(this)->Find(name);
}

bool FlagSet::NamesAFlag(std::string_view word) const {
  if (word.size() <= 2 || word.substr(0, 2) != "--") return false;
  return IsHelp(word) || Find(FlagName(word)) != nullptr;
}

bool FlagSet::Given(std::string_view name) const {
  const Flag* flag = Find(name);
  return flag != nullptr && flag->times_given > 0;
}

Status FlagSet::Parse(int argc, const char* const* argv) {
  std::vector<std::string> args;
  for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
  return Parse(args);
}

Status FlagSet::Parse(const std::vector<std::string>& args) {
  help_requested_ = false;
  for (Flag& flag : flags_) flag.times_given = 0;
  // --help wins over whatever else the line holds, mistakes included.
  for (const std::string& word : args) {
    if (word == "--") break;
    if (IsHelp(word)) {
      help_requested_ = true;
      return Status::OK();
    }
  }
  bool only_positionals = false;
  for (size_t next = 0; next < args.size();) {
    const std::string& word = args[next++];
    if (!only_positionals && word == "--") {
      only_positionals = true;
      continue;
    }
    if (!only_positionals && word.size() > 2 && word.starts_with("--")) {
      if (Status status = ParseFlag(word, args, &next); !status.ok()) {
        return status;
      }
      continue;
    }
    if (positionals_ == nullptr) {
      return Status::InvalidArgument("unexpected argument '" + word + "'");
    }
    positionals_->push_back(word);
  }
  return Status::OK();
}

Status FlagSet::ParseFlag(std::string_view word,
                          const std::vector<std::string>& args, size_t* next) {
  const std::string_view name = FlagName(word);
  Flag* flag = Find(name);
  if (flag == nullptr) {
    return Status::InvalidArgument("unknown flag --" + std::string(name));
  }
  const FlagValue& value = flag->value;
  const std::string dashed = "--" + flag->name;
  if (flag->times_given > 0 && !value.repeatable) {
    return Status::InvalidArgument(dashed + " is given twice");
  }
  std::vector<std::string> words;
  if (const size_t equals = word.find('='); equals != std::string_view::npos) {
    words.emplace_back(word.substr(equals + 1));
    if (value.words == 0) {
      return Status::InvalidArgument(dashed + " takes no value, not '" +
                                     words[0] + "'");
    }
  }
  while (words.size() < value.words) {
    if (*next == args.size() || NamesAFlag(args[*next])) {
      return Status::InvalidArgument(
          dashed + " needs " +
          (value.words == 1 ? std::string("a value")
                            : std::to_string(value.words) + " values") +
          " (" + value.shape + ")");
    }
    words.push_back(args[(*next)++]);
  }
  ++flag->times_given;
  Status parsed = value.parse(words);
  if (parsed.ok()) return parsed;
  std::string text;
  for (const std::string& w : words) {
    if (!text.empty()) text += ' ';
    text += w;
  }
  return FlagError(flag->name, text, parsed.message());
}

std::string FlagSet::Help() const {
  std::string help = usage_;
  while (!help.empty() && help.back() == '\n') help.pop_back();
  help += "\n\nflags:\n";
  const auto add = [&help](std::string head, std::string_view text) {
    help += "  " + head;
    const size_t used = 2 + head.size();
    if (used + 2 > kHelpColumn) {
      help += "\n" + std::string(kHelpColumn, ' ');
    } else {
      help += std::string(kHelpColumn - used, ' ');
    }
    AppendWrapped(text, &help);
    help += "\n";
  };
  for (const Flag& flag : flags_) {
    std::string head = "--" + flag.name;
    if (flag.value.words > 0) head += " " + flag.value.shape;
    std::string text = flag.help;
    if (!flag.value.default_text.empty()) {
      text += " (default: " + flag.value.default_text + ")";
    }
    add(std::move(head), text);
  }
  add("--help, -h", "print this help and exit");
  return help;
}

std::optional<int> ExitCodeForFlags(std::string_view program,
                                    const Status& parsed,
                                    const std::string& help) {
  if (!parsed.ok()) {
    std::cerr << program << ": " << parsed.message() << "\n(see " << program
              << " --help)" << std::endl;
    return 2;
  }
  if (!help.empty()) {
    std::cout << help;
    return 0;
  }
  return std::nullopt;
}

}  // namespace locator
