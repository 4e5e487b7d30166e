#pragma once
// One line of a report for the log, its severity stated by the code that knows it, not read back from
// the text (issue 15: the editor and the CLI looked for a "warning: " prefix).
#include <string>

namespace kerf {

enum class Severity { Info, Warning };

struct ReportLine {
  Severity severity = Severity::Info;
  std::string text;
};

inline const char* severityName(Severity severity) {
  return severity == Severity::Warning ? "warning" : "info";
}

}  // namespace kerf
