#include "legofeup/lessons/analysis/analysis_tables.hpp"

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>

#include "json_integer.hpp"
#include "legofeup/lessons/run_summary.hpp"

namespace legofeup::lessons::analysis {
namespace {

template <class Record>
struct Field {
    const char* name;
    double Record::*member;
};

// The numeric columns of the tables, in order; also the JSON names.
constexpr std::array kRunFields = {
    Field<RunRecord>{"rms_position_error_m", &RunRecord::rms_position_error},
    Field<RunRecord>{"max_position_error_m", &RunRecord::max_position_error},
    Field<RunRecord>{"final_position_error_m", &RunRecord::final_position_error},
    Field<RunRecord>{"rms_heading_error_rad", &RunRecord::rms_heading_error},
    Field<RunRecord>{"final_heading_error_rad", &RunRecord::final_heading_error},
    Field<RunRecord>{"mean_nees", &RunRecord::mean_nees},
    Field<RunRecord>{"nees_inside_fraction", &RunRecord::nees_inside_fraction},
    Field<RunRecord>{"mean_nis", &RunRecord::mean_nis},
    Field<RunRecord>{"nees_effective_samples", &RunRecord::nees_effective_samples},
    Field<RunRecord>{"time_average_nees_lower", &RunRecord::time_average_nees_lower},
    Field<RunRecord>{"time_average_nees_upper", &RunRecord::time_average_nees_upper},
};

constexpr std::array kCellFields = {
    Field<SweepCell>{"q_scale", &SweepCell::q_scale},
    Field<SweepCell>{"r_scale", &SweepCell::r_scale},
    Field<SweepCell>{"rms_position_error_m", &SweepCell::rms_position_error},
    Field<SweepCell>{"final_position_error_m", &SweepCell::final_position_error},
    Field<SweepCell>{"mean_nees", &SweepCell::mean_nees},
    Field<SweepCell>{"nees_inside_fraction", &SweepCell::nees_inside_fraction},
    Field<SweepCell>{"mean_nis", &SweepCell::mean_nis},
    Field<SweepCell>{"nis_inside_fraction", &SweepCell::nis_inside_fraction},
    Field<SweepCell>{"consistency_log10_nees_over_3", &SweepCell::consistency},
};

/// JSON has no NaN: null stands for "none" (no update, no finite NEES).
nlohmann::json number(double value) {
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json(nullptr);
}

double number_from(const nlohmann::json& json) {
    return json.is_null() ? std::numeric_limits<double>::quiet_NaN() : json.get<double>();
}

/// A CSV cell: full precision, empty for none.
std::string cell(double value) {
    if (!std::isfinite(value)) {
        return "";
    }
    char text[32];
    std::snprintf(text, sizeof text, "%.10g", value);
    return text;
}

nlohmann::json interval(const ChiSquareInterval& bounds) {
    return {number(bounds.lower), number(bounds.upper)};
}

nlohmann::json distribution(const Distribution& d) {
    return {{"mean", number(d.mean)}, {"std", number(d.stddev)}, {"min", number(d.min)},
            {"max", number(d.max)},   {"p5", number(d.p5)},      {"median", number(d.median)},
            {"p95", number(d.p95)}};
}

template <class Record, std::size_t N>
void add_fields(nlohmann::json& json, const Record& record,
                const std::array<Field<Record>, N>& fields) {
    for (const Field<Record>& field : fields) {
        json[field.name] = number(record.*field.member);
    }
}

template <class Record, std::size_t N>
void read_fields(const nlohmann::json& json, Record& record,
                 const std::array<Field<Record>, N>& fields) {
    for (const Field<Record>& field : fields) {
        record.*field.member = number_from(json.at(field.name));
    }
}

template <class Record, std::size_t N>
void csv_header(std::string& text, const std::array<Field<Record>, N>& fields) {
    for (const Field<Record>& field : fields) {
        text += std::string(",") + field.name;
    }
    text += '\n';
}

template <class Record, std::size_t N>
void csv_row(std::string& text, const Record& record, const std::array<Field<Record>, N>& fields) {
    for (const Field<Record>& field : fields) {
        text += "," + cell(record.*field.member);
    }
    text += '\n';
}

}  // namespace

nlohmann::json to_json(const BatchHeader& header) {
    nlohmann::json json = {
        {"kind", header.kind},
        {"experiment", header.experiment},
        {"title", header.title},
        {"runs", header.runs},
        {"first_seed", header.first_seed},
        {"control_period_s", header.control_period},
    };
    if (header.kind == "sweep") {
        json["q_scales"] = header.q_scales;
        json["r_scales"] = header.r_scales;
    }
    json["config"] = header.configuration;
    return json;
}

BatchHeader batch_header_from_json(const nlohmann::json& json) {
    BatchHeader header;
    header.kind = json.at("kind").get<std::string>();
    header.experiment = json.at("experiment").get<std::string>();
    header.title = json.at("title").get<std::string>();
    header.runs = json_integer_at<std::size_t>(json, "runs");
    header.first_seed = json_integer_at<std::uint64_t>(json, "first_seed");
    header.control_period = json.at("control_period_s").get<double>();
    if (header.kind == "sweep") {
        header.q_scales = json.at("q_scales").get<std::vector<double>>();
        header.r_scales = json.at("r_scales").get<std::vector<double>>();
    }
    header.configuration = json.at("config");
    return header;
}

namespace {

BatchHeader make_header(const std::string& kind, const RunConfig& config, std::size_t runs,
                        std::uint64_t first_seed, const std::string& experiment,
                        const std::string& title) {
    RunConfig base = config;
    base.seed = first_seed;  // every run sets its own: keep the base's out of the identity
    return {kind,
            experiment,
            title,
            config_to_json(base),
            runs,
            first_seed,
            config.simulator.control_period,
            {},
            {}};
}

}  // namespace

BatchHeader monte_carlo_header(const MonteCarloSpec& spec, const std::string& experiment,
                               const std::string& title) {
    return make_header("montecarlo", spec.config, spec.runs, spec.first_seed, experiment, title);
}

BatchHeader sweep_header(const SweepSpec& spec, const std::string& experiment,
                         const std::string& title) {
    BatchHeader header =
        make_header("sweep", spec.config, spec.runs, spec.first_seed, experiment, title);
    header.q_scales = spec.q_scales;
    header.r_scales = spec.r_scales;
    return header;
}

std::string header_hash(const BatchHeader& header) {
    // FNV-1a, 64 bits.
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    for (const char c : to_json(header).dump()) {
        hash = (hash ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;
    }
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

nlohmann::json monte_carlo_summary_json(const BatchHeader& header,
                                        const MonteCarloSummary& summary) {
    nlohmann::json json = to_json(header);
    // Bounds of the averages over all N runs, where every run is present (the first step).
    const StepStatistics* first = summary.steps.empty() ? nullptr : &summary.steps.front();
    json["aggregate"] = {
        {"runs", summary.runs.size()},
        {"runs_finished", summary.runs_finished},
        {"steps", summary.steps.size()},
        {"rms_position_error_m", distribution(summary.rms_position_error)},
        {"final_position_error_m", distribution(summary.final_position_error)},
        {"rms_heading_error_rad", distribution(summary.rms_heading_error)},
        {"mean_nees", number(summary.mean_nees)},
        {"time_average_nees_95_bounds", interval(summary.time_average_nees_bounds)},
        {"nees_dispersion", number(summary.nees_dispersion)},
        {"runs_nees_inside_time_average_fraction",
         number(summary.runs_nees_inside_time_average_fraction)},
        {"averaged_nees_95_bounds_all_runs",
         first != nullptr ? interval(first->nees_bounds) : nlohmann::json(nullptr)},
        {"nees_inside_fraction", number(summary.nees_inside_fraction)},
        {"mean_nis", number(summary.mean_nis)},
        {"nis_inside_fraction", number(summary.nis_inside_fraction)},
    };
    json["files"] = {{"steps", "steps.csv"}, {"runs", "runs.csv"}};
    return json;
}

std::string monte_carlo_steps_csv(const MonteCarloSummary& summary) {
    std::string text =
        "step,time_s,runs,nees_runs,mean_nees,nees_lower,nees_upper,nis_runs,mean_nis,"
        "nis_lower,nis_upper,rms_position_error_m,rms_heading_error_rad\n";
    for (const StepStatistics& s : summary.steps) {
        text += std::to_string(s.step) + "," + cell(s.time) + "," + std::to_string(s.runs) + ","
                + std::to_string(s.nees_runs) + "," + cell(s.mean_nees) + ","
                + cell(s.nees_bounds.lower) + "," + cell(s.nees_bounds.upper) + ","
                + std::to_string(s.nis_runs) + "," + cell(s.mean_nis) + ","
                + cell(s.nis_bounds.lower) + "," + cell(s.nis_bounds.upper) + ","
                + cell(s.rms_position_error) + "," + cell(s.rms_heading_error) + "\n";
    }
    return text;
}

std::string monte_carlo_runs_csv(const std::vector<RunRecord>& runs) {
    std::string text = "run,seed,routine_finished,steps,updates_applied";
    csv_header(text, kRunFields);
    for (const RunRecord& run : runs) {
        text += std::to_string(run.index) + "," + std::to_string(run.seed) + ","
                + (run.routine_finished ? "1" : "0") + "," + std::to_string(run.steps) + ","
                + std::to_string(run.updates_applied);
        csv_row(text, run, kRunFields);
    }
    return text;
}

nlohmann::json sweep_summary_json(const BatchHeader& header, const std::vector<SweepCell>& cells) {
    nlohmann::json json = to_json(header);
    nlohmann::json list = nlohmann::json::array();
    const SweepCell* lowest_error = nullptr;
    const SweepCell* most_consistent = nullptr;
    for (const SweepCell& c : cells) {
        list.push_back(to_json(c));
        if (std::isfinite(c.rms_position_error)
            && (lowest_error == nullptr
                || c.rms_position_error < lowest_error->rms_position_error)) {
            lowest_error = &c;
        }
        if (std::isfinite(c.consistency)
            && (most_consistent == nullptr
                || std::abs(c.consistency) < std::abs(most_consistent->consistency))) {
            most_consistent = &c;
        }
    }
    json["cells"] = list;
    json["lowest_rms_position_error"] =
        lowest_error != nullptr ? to_json(*lowest_error) : nlohmann::json(nullptr);
    json["most_consistent"] =
        most_consistent != nullptr ? to_json(*most_consistent) : nlohmann::json(nullptr);
    json["files"] = {{"cells", "cells.csv"}};
    return json;
}

std::string sweep_cells_csv(const std::vector<SweepCell>& cells) {
    std::string text = "cell,q_index,r_index,runs";
    csv_header(text, kCellFields);
    for (const SweepCell& c : cells) {
        text += std::to_string(c.index) + "," + std::to_string(c.q_index) + ","
                + std::to_string(c.r_index) + "," + std::to_string(c.runs);
        csv_row(text, c, kCellFields);
    }
    return text;
}

nlohmann::json to_json(const RunRecord& run) {
    nlohmann::json json = {
        {"run", run.index},
        {"seed", run.seed},
        {"routine_finished", run.routine_finished},
        {"steps", run.steps},
        {"updates_applied", run.updates_applied},
    };
    add_fields(json, run, kRunFields);
    return json;
}

RunRecord run_record_from_json(const nlohmann::json& json) {
    RunRecord run;
    run.index = json_integer_at<std::size_t>(json, "run");
    run.seed = json_integer_at<std::uint64_t>(json, "seed");
    run.routine_finished = json.at("routine_finished").get<bool>();
    run.steps = json_integer_at<std::uint64_t>(json, "steps");
    run.updates_applied = json_integer_at<std::uint64_t>(json, "updates_applied");
    read_fields(json, run, kRunFields);
    return run;
}

nlohmann::json to_json(const SweepCell& c) {
    nlohmann::json json = {
        {"cell", c.index}, {"q_index", c.q_index}, {"r_index", c.r_index}, {"runs", c.runs}};
    add_fields(json, c, kCellFields);
    return json;
}

SweepCell sweep_cell_from_json(const nlohmann::json& json) {
    SweepCell c;
    c.index = json_integer_at<std::size_t>(json, "cell");
    c.q_index = json_integer_at<std::size_t>(json, "q_index");
    c.r_index = json_integer_at<std::size_t>(json, "r_index");
    c.runs = json_integer_at<std::size_t>(json, "runs");
    read_fields(json, c, kCellFields);
    return c;
}

}  // namespace legofeup::lessons::analysis
