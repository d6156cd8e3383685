#pragma once
// Reporting what is wrong with a configuration: one issue per bad field, found by a checker
// shared by every validate() in the project, so all of them word their reasons alike.

#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace legofeup {

/// One problem with a configuration: which field, what value, and why it was refused.
struct ConfigIssue {
    std::string field;   ///< e.g. "filter.q11"
    std::string value;   ///< the offending value as text
    std::string reason;  ///< e.g. "must be between 1e-15 and 1e+09"

    std::string message() const;  ///< "filter.q11 = -1: must be …"
};

/// A number as issues show it ("%.6g": 1e-07, 0.12, nan).
std::string format_config_number(double value);

/// Collects issues into a list; each check adds one when its condition fails.
class ConfigChecker {
  public:
    explicit ConfigChecker(std::vector<ConfigIssue>& issues) : issues_(issues) {}

    void require(bool ok, const std::string& field, double value, const std::string& reason);
    void finite(const std::string& field, double value);
    /// low ≤ value ≤ high.
    void in_range(const std::string& field, double value, double low, double high);
    /// low ≤ value ≤ high, or exactly 0 (0 meaning "automatic").
    void in_range_or_zero(const std::string& field, double value, double low, double high);
    /// 0 < value ≤ high.
    void positive(const std::string& field, double value, double high);

  private:
    std::vector<ConfigIssue>& issues_;
};

/// Every issue's message, joined by `separator`.
std::string join_issue_messages(const std::vector<ConfigIssue>& issues, std::string_view separator);

/// The exception a constructor throws for an invalid configuration: "invalid <what>
/// configuration:" followed by one issue per line.
std::invalid_argument invalid_configuration(std::string_view what,
                                            const std::vector<ConfigIssue>& issues);

}  // namespace legofeup
