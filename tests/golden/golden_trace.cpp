#include "golden_trace.hpp"

#include <bit>
#include <cinttypes>
#include <cstdio>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "legofeup/lessons/config_file.hpp"
#include "legofeup/lessons/lockstep_run.hpp"
#include "legofeup/lessons/trace_csv.hpp"
#include "trace_hash_test_support.hpp"

namespace legofeup::lessons::golden_testing {
namespace {

using hash_testing::fnv1a_64;

constexpr std::uint64_t kGoldenSeed = 1;
constexpr const char* kGoldenExperiment = "f";

/// FNV-1a 64 continued over the `size` least significant bytes of `value`, least significant
/// first (the same bytes on any host).
void hash_bytes(std::uint64_t& hash, std::uint64_t value, int size) {
    for (int i = 0; i < size; ++i) {
        hash = (hash ^ ((value >> (8 * i)) & 0xFFU)) * 0x100000001b3ULL;
    }
}

/// Writes trace.csv as the CLI does and hashes the bit patterns the CSV rounds.
class FingerprintObserver final : public RunObserver {
  public:
    FingerprintObserver(std::ostream& csv, const LoopConfig& loop) : writer_(csv, loop) {}

    void on_step(const LoopSnapshot& s, const GroundTruth& truth) override {
        writer_.on_step(s, truth);
        const StateCovariance& P = s.covariance;
        for (const double value :
             {truth.pose.x, truth.pose.y, truth.pose.theta, s.estimate(kX), s.estimate(kY),
              s.estimate(kTheta), P(kX, kX), P(kX, kY), P(kX, kTheta), P(kY, kY), P(kY, kTheta),
              P(kTheta, kTheta), s.odometry_pose.x, s.odometry_pose.y, s.odometry_pose.theta}) {
            hash_bytes(bits_, std::bit_cast<std::uint64_t>(value), 8);
        }
        for (const std::int32_t count : s.frame.encoder_counts) {
            hash_bytes(bits_, static_cast<std::uint32_t>(count), 4);
        }
        for (const std::uint16_t adc : s.frame.ir_adc) {
            hash_bytes(bits_, adc, 2);
        }
    }

    std::uint64_t bits() const { return bits_; }

  private:
    TraceCsvWriter writer_;
    std::uint64_t bits_ = fnv1a_64("");  // the offset basis
};

std::vector<std::string> split(const std::string& line, char separator) {
    std::vector<std::string> parts;
    std::size_t start = 0;
    for (std::size_t end; (end = line.find(separator, start)) != std::string::npos;
         start = end + 1) {
        parts.push_back(line.substr(start, end - start));
    }
    parts.push_back(line.substr(start));
    return parts;
}

std::string hex(std::uint64_t hash) {
    char text[17];
    std::snprintf(text, sizeof text, "%016" PRIx64, hash);
    return text;
}

std::uint64_t parse_hex(const std::string& text, const std::string& where) {
    const bool well_formed =
        text.size() == 16 && text.find_first_not_of("0123456789abcdef") == std::string::npos;
    if (!well_formed) {
        throw std::runtime_error(where + ": \"" + text
                                 + "\" is not a hash (16 lower-case hexadecimal digits)");
    }
    return std::stoull(text, nullptr, 16);
}

}  // namespace

TraceFingerprint golden_run_fingerprint(std::string* trace_csv) {
    // What `legofeup-cli run -e f --seed 1` runs (app/cli/config_choice.cpp).
    const ResolvedRun run = resolve(compose_config({kGoldenExperiment, {}, kGoldenSeed}));
    std::ostringstream csv;
    FingerprintObserver observer(csv, run.loop);
    run_lockstep(run, &observer);
    TraceFingerprint fingerprint = text_fingerprint(csv.str());
    fingerprint.bits = observer.bits();
    if (trace_csv != nullptr) {
        *trace_csv = csv.str();
    }
    return fingerprint;
}

TraceFingerprint text_fingerprint(const std::string& trace_csv) {
    TraceFingerprint fingerprint;
    fingerprint.trace = fnv1a_64(trace_csv);
    std::istringstream lines(trace_csv);
    std::string line;
    std::getline(lines, line);
    const std::vector<std::string> names = split(line, ',');
    std::vector<std::string> cells_by_column(names.size());
    while (std::getline(lines, line)) {
        const std::vector<std::string> cells = split(line, ',');
        for (std::size_t i = 0; i < cells.size() && i < names.size(); ++i) {
            cells_by_column[i] += cells[i] + '\n';
        }
        ++fingerprint.rows;
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
        fingerprint.columns[names[i]] = fnv1a_64(cells_by_column[i]);
    }
    return fingerprint;
}

std::string to_pinned_text(const TraceFingerprint& fingerprint) {
    std::string text =
        "# The golden trace: experiment f, seed 1 (tests/golden/golden_trace.hpp says what each\n"
        "# line hashes). Checked by tests/golden/test_golden_trace.cpp; renew with "
        + std::string(kRenewCommand) + ".\n";
    text += "trace " + hex(fingerprint.trace) + '\n';
    text += "bits " + hex(fingerprint.bits) + '\n';
    text += "rows " + std::to_string(fingerprint.rows) + '\n';
    for (const auto& [name, hash] : fingerprint.columns) {
        text += "column " + name + ' ' + hex(hash) + '\n';
    }
    return text;
}

TraceFingerprint parse_pinned_text(const std::string& text, const std::string& file) {
    TraceFingerprint fingerprint;
    std::istringstream lines(text);
    int number = 0;
    bool have_trace = false;
    bool have_bits = false;
    bool have_rows = false;
    for (std::string line; std::getline(lines, line);) {
        ++number;
        if (line.empty() || line.front() == '#') {
            continue;
        }
        const std::string where = file + ":" + std::to_string(number);
        const std::vector<std::string> words = split(line, ' ');
        if (words.size() == 2 && words[0] == "trace") {
            fingerprint.trace = parse_hex(words[1], where);
            have_trace = true;
        } else if (words.size() == 2 && words[0] == "bits") {
            fingerprint.bits = parse_hex(words[1], where);
            have_bits = true;
        } else if (words.size() == 2 && words[0] == "rows"
                   && words[1].find_first_not_of("0123456789") == std::string::npos
                   && !words[1].empty() && words[1].size() < 19) {
            fingerprint.rows = std::stoull(words[1]);
            have_rows = true;
        } else if (words.size() == 3 && words[0] == "column" && !words[1].empty()) {
            fingerprint.columns[words[1]] = parse_hex(words[2], where);
        } else {
            throw std::runtime_error(where + ": \"" + line
                                     + "\": expected \"trace <hash>\", \"bits <hash>\", "
                                       "\"rows <count>\" or \"column <name> <hash>\"");
        }
    }
    if (!have_trace || !have_bits || !have_rows) {
        throw std::runtime_error(file + ": the trace, bits and rows lines are all required");
    }
    return fingerprint;
}

std::string describe_change(const TraceFingerprint& pinned, const TraceFingerprint& now) {
    std::string text;
    const auto line = [&text](const char* name, const std::string& was, const std::string& is) {
        if (was != is) {
            text += std::string("  ") + name + ": " + was + " -> " + is + '\n';
        }
    };
    line("trace.csv hash", hex(pinned.trace), hex(now.trace));
    line("bit-pattern hash", hex(pinned.bits), hex(now.bits));
    line("rows", std::to_string(pinned.rows), std::to_string(now.rows));
    std::string changed;
    std::string gone;
    for (const auto& [name, hash] : pinned.columns) {
        const auto found = now.columns.find(name);
        if (found == now.columns.end()) {
            gone += " " + name;
        } else if (found->second != hash) {
            changed += " " + name;
        }
    }
    std::string added;
    for (const auto& [name, hash] : now.columns) {
        added += pinned.columns.contains(name) ? "" : " " + name;
    }
    const auto columns = [&text](const char* what, const std::string& names) {
        if (!names.empty()) {
            text += std::string("  columns ") + what + ":" + names + '\n';
        }
    };
    columns("changed", changed);
    columns("no longer written", gone);
    columns("new", added);
    return text;
}

}  // namespace legofeup::lessons::golden_testing
