#include "legofeup/lessons/analysis/sweep.hpp"

#include <charconv>
#include <cmath>
#include <optional>

#include "legofeup/lessons/analysis/monte_carlo.hpp"
#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons::analysis {
namespace {

std::optional<double> number(std::string_view text) {
    double value = 0.0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size()) {
        return std::nullopt;
    }
    return value;
}

std::vector<std::string_view> split(std::string_view text, char separator) {
    std::vector<std::string_view> parts;
    for (;;) {
        const std::size_t at = text.find(separator);
        parts.push_back(text.substr(0, at));
        if (at == std::string_view::npos) {
            return parts;
        }
        text.remove_prefix(at + 1);
    }
}

SweepCell cell_result(const SweepSpec& spec, std::size_t index, const MonteCarloSums& sums) {
    const MonteCarloSummary summary = summarize(sums, spec.config.simulator.control_period);
    SweepCell cell;
    cell.index = index;
    cell.q_index = index / spec.r_scales.size();
    cell.r_index = index % spec.r_scales.size();
    cell.q_scale = spec.q_scales[cell.q_index];
    cell.r_scale = spec.r_scales[cell.r_index];
    cell.runs = sums.runs.size();
    cell.rms_position_error = summary.rms_position_error.mean;
    cell.final_position_error = summary.final_position_error.mean;
    cell.mean_nees = summary.mean_nees;
    cell.nees_inside_fraction = summary.nees_inside_fraction;
    cell.mean_nis = summary.mean_nis;
    cell.nis_inside_fraction = summary.nis_inside_fraction;
    cell.consistency = std::log10(summary.mean_nees / kStateSize);
    return cell;
}

}  // namespace

std::vector<double> parse_scales(const std::string& text, const std::string& option) {
    const auto fail = [&](const std::string& reason) {
        return InputError({{"", 0, option, text, reason}});
    };
    const auto factor = [&](std::string_view part) {
        const std::optional<double> value = number(part);
        if (!value) {
            throw fail("\"" + std::string(part) + "\" is not a number");
        }
        if (!(*value > 0.0) || !std::isfinite(*value)) {
            throw fail("factors must be positive and finite, not " + std::string(part));
        }
        return *value;
    };
    const std::vector<std::string_view> range = split(text, ':');
    if (range.size() == 3) {
        const double low = factor(range[0]);
        const double high = factor(range[1]);
        const std::optional<double> count = number(range[2]);
        if (!count || *count < 2 || *count > 1000 || std::floor(*count) != *count) {
            throw fail("LOW:HIGH:COUNT needs a whole COUNT from 2 to 1000, not \""
                       + std::string(range[2]) + "\"");
        }
        const auto n = static_cast<std::size_t>(*count);
        std::vector<double> values;
        const double decades = std::log10(high) - std::log10(low);
        for (std::size_t i = 0; i < n; ++i) {
            const double fraction = static_cast<double>(i) / static_cast<double>(n - 1);
            values.push_back(i == 0       ? low
                             : i == n - 1 ? high
                                          : std::pow(10.0, std::log10(low) + fraction * decades));
        }
        return values;
    }
    if (range.size() != 1) {
        throw fail("expected a list like 0.1,1,10 or a range LOW:HIGH:COUNT like 1e-2:1e2:5");
    }
    std::vector<double> values;
    for (const std::string_view part : split(text, ',')) {
        values.push_back(factor(part));
    }
    return values;
}

std::vector<SweepCell> run_sweep(const SweepSpec& spec, int jobs, const Shard& shard,
                                 const BatchProgress& progress) {
    if (spec.runs == 0 || spec.cell_count() == 0) {
        throw InputError({{"", 0,
                           spec.runs == 0          ? "--runs"
                           : spec.q_scales.empty() ? "--q"
                                                   : "--r",
                           "", "a sweep needs at least one run and one factor each for Q and R"}});
    }
    std::vector<std::size_t> cells;  // the cells of this shard
    std::vector<ResolvedRun> runs;   // their runs, cell by cell
    for (std::size_t index = 0; index < spec.cell_count(); ++index) {
        if (!shard.takes(index)) {
            continue;
        }
        RunConfig config = spec.config;
        const double q = spec.q_scales[index / spec.r_scales.size()];
        const double r = spec.r_scales[index % spec.r_scales.size()];
        config.filter.q11 *= q;
        config.filter.q22 *= q;
        config.filter.r11 *= r;
        config.filter.r22 *= r;
        ResolvedRun base = resolve(config);
        for (std::size_t run = 0; run < spec.runs; ++run) {
            base.config.seed = spec.first_seed + run;
            runs.push_back(base);
        }
        cells.push_back(index);
    }
    std::vector<SweepCell> results;
    MonteCarloSums sums;  // of the cell being consumed; runs arrive cell after cell
    run_recorded(
        runs, jobs,
        [&](std::size_t k, const RunResult& result, const std::vector<StepSample>& samples) {
            const std::size_t run = k % spec.runs;
            sums.add_run(make_run_record(run, spec.first_seed + run, result), samples);
            if (run + 1 == spec.runs) {
                results.push_back(cell_result(spec, cells[k / spec.runs], sums));
                sums = {};
            }
        },
        progress);
    return results;
}

}  // namespace legofeup::lessons::analysis
