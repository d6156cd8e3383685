#include "legofeup/lessons/analysis/shard_file.hpp"

#include <algorithm>
#include <map>

#include "../text_file.hpp"
#include "json_integer.hpp"
#include "legofeup/lessons/input_error.hpp"

namespace legofeup::lessons::analysis {
namespace {

constexpr const char* kFormat = "legofeup-shard";

// The per-step columns of a Monte Carlo shard.
struct SumColumn {
    const char* name;
    ExactSum StepSums::*member;
};
constexpr SumColumn kSumColumns[] = {
    {"nees", &StepSums::nees},
    {"nis", &StepSums::nis},
    {"position_squared", &StepSums::position_squared},
    {"heading_squared", &StepSums::heading_squared},
};
struct CountColumn {
    const char* name;
    std::uint64_t StepSums::*member;
};
constexpr CountColumn kCountColumns[] = {
    {"runs", &StepSums::runs},
    {"nees_runs", &StepSums::nees_runs},
    {"nis_runs", &StepSums::nis_runs},
};

std::string shard_text(const Shard& shard) {
    return std::to_string(shard.index) + "/" + std::to_string(shard.count);
}

nlohmann::json shard_document(const BatchHeader& header, const Shard& shard) {
    return {
        {"format", kFormat},
        {"format_version", kShardFormatVersion},
        {"kind", header.kind},
        {"shard", {{"index", shard.index}, {"count", shard.count}}},
        {"configuration_hash", header_hash(header)},
        {"header", to_json(header)},
    };
}

nlohmann::json steps_json(const std::vector<StepSums>& steps) {
    nlohmann::json json = nlohmann::json::object();
    for (const CountColumn& column : kCountColumns) {
        nlohmann::json values = nlohmann::json::array();
        for (const StepSums& step : steps) {
            values.push_back(step.*column.member);
        }
        json[column.name] = std::move(values);
    }
    for (const SumColumn& column : kSumColumns) {
        nlohmann::json values = nlohmann::json::array();
        for (const StepSums& step : steps) {
            values.push_back((step.*column.member).to_text());
        }
        json[column.name] = std::move(values);
    }
    return json;
}

// A per-step column of a shard, checked to have one value per step.
const nlohmann::json& step_column(const nlohmann::json& steps, const char* name,
                                  std::size_t count) {
    const nlohmann::json& values = steps.at(name);
    if (values.size() != count) {
        throw std::runtime_error(std::string("steps.") + name + " has "
                                 + std::to_string(values.size()) + " values, steps.runs "
                                 + std::to_string(count));
    }
    return values;
}

std::vector<StepSums> steps_from_json(const nlohmann::json& json) {
    const std::size_t count = json.at("runs").size();
    std::vector<StepSums> steps(count);
    for (const CountColumn& column : kCountColumns) {
        const nlohmann::json& values = step_column(json, column.name, count);
        for (std::size_t k = 0; k < count; ++k) {
            steps[k].*column.member = json_integer<std::uint64_t>(
                values[k], std::string("steps.") + column.name + "[" + std::to_string(k) + "]");
        }
    }
    for (const SumColumn& column : kSumColumns) {
        const nlohmann::json& values = step_column(json, column.name, count);
        for (std::size_t k = 0; k < count; ++k) {
            const auto sum = ExactSum::from_text(values[k].get<std::string>());
            if (!sum) {
                throw std::runtime_error(std::string("steps.") + column.name + "["
                                         + std::to_string(k) + "] is not an exact sum");
            }
            steps[k].*column.member = *sum;
        }
    }
    return steps;
}

}  // namespace

nlohmann::json monte_carlo_shard(const BatchHeader& header, const Shard& shard,
                                 const MonteCarloSums& sums) {
    nlohmann::json json = shard_document(header, shard);
    nlohmann::json runs = nlohmann::json::array();
    for (const RunRecord& run : sums.runs) {
        runs.push_back(to_json(run));
    }
    json["run_records"] = std::move(runs);
    json["steps"] = steps_json(sums.steps);
    return json;
}

nlohmann::json sweep_shard(const BatchHeader& header, const Shard& shard,
                           const std::vector<SweepCell>& cells) {
    nlohmann::json json = shard_document(header, shard);
    nlohmann::json list = nlohmann::json::array();
    for (const SweepCell& cell : cells) {
        list.push_back(to_json(cell));
    }
    json["cells"] = std::move(list);
    return json;
}

ShardFile parse_shard_file(const std::string& text, const std::string& source) {
    const auto fail = [&](const std::string& key, const std::string& value,
                          const std::string& reason) {
        return InputError({{source, 0, key, value, reason}});
    };
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& error) {
        throw fail("", "", std::string("not a shard file (not JSON): ") + error.what());
    }
    if (!json.is_object() || !json.contains("format") || json["format"] != kFormat) {
        throw fail("format", "",
                   std::string("not a shard file (written by legofeup-cli "
                               "montecarlo or sweep with --shard)"));
    }
    // Compared as JSON, not read as an int: a version of 1e300 is a wrong version, not a
    // cast out of range.
    const nlohmann::json version = json.value("format_version", nlohmann::json(0));
    if (version != kShardFormatVersion) {
        throw fail("format_version", version.dump(),
                   "this legofeup-cli reads shard format " + std::to_string(kShardFormatVersion)
                       + "; write the shards again with it");
    }
    ShardFile file;
    file.source = source;
    try {
        file.header = batch_header_from_json(json.at("header"));
        file.shard = {json_integer_at<int>(json.at("shard"), "index"),
                      json_integer_at<int>(json.at("shard"), "count")};
        if (file.header.kind == "montecarlo") {
            for (const nlohmann::json& run : json.at("run_records")) {
                file.sums.runs.push_back(run_record_from_json(run));
            }
            file.sums.steps = steps_from_json(json.at("steps"));
        } else if (file.header.kind == "sweep") {
            for (const nlohmann::json& cell : json.at("cells")) {
                file.cells.push_back(sweep_cell_from_json(cell));
            }
        } else {
            throw fail("kind", file.header.kind, "expected montecarlo or sweep");
        }
    } catch (const nlohmann::json::exception& error) {
        throw fail("", "", std::string("damaged shard file: ") + error.what());
    } catch (const std::runtime_error& error) {
        if (dynamic_cast<const InputError*>(&error) != nullptr) {
            throw;
        }
        throw fail("", "", std::string("damaged shard file: ") + error.what());
    }
    if (file.shard.count < 1 || file.shard.index < 1 || file.shard.index > file.shard.count) {
        throw fail("shard", shard_text(file.shard), "not a shard i/n with 1 ≤ i ≤ n");
    }
    return file;
}

ShardFile read_shard_file(const std::filesystem::path& path) {
    return parse_shard_file(read_text_file(path, kShardFile), path.string());
}

MergedBatch merge_shards(const std::vector<ShardFile>& shards) {
    if (shards.empty()) {
        throw InputError({{"", 0, "merge", "", "no shard files given"}});
    }
    const ShardFile& first = shards.front();
    std::vector<InputProblem> problems;
    bool unrelated = false;  // then which shards are missing says nothing useful
    std::map<int, const ShardFile*> by_index;
    for (const ShardFile& shard : shards) {
        const BatchHeader& a = first.header;
        const BatchHeader& b = shard.header;
        const auto differs = [&](const std::string& key, const std::string& value,
                                 const std::string& first_value) {
            problems.push_back({shard.source, 0, key, value,
                                "differs from " + first.source + " (" + first_value
                                    + "): the shards are not of one batch"});
            unrelated = true;
        };
        if (b.kind != a.kind) {
            differs("kind", b.kind, a.kind);
            continue;
        }
        if (b.configuration != a.configuration || b.experiment != a.experiment) {
            differs("configuration", header_hash(b), header_hash(a));
        } else if (b.runs != a.runs) {
            differs("runs", std::to_string(b.runs), std::to_string(a.runs));
        } else if (b.first_seed != a.first_seed) {
            differs("first_seed", std::to_string(b.first_seed), std::to_string(a.first_seed));
        } else if (b.q_scales != a.q_scales || b.r_scales != a.r_scales) {
            differs("q_scales/r_scales", "", "another grid");
        } else if (!(b == a)) {
            differs("header", header_hash(b), header_hash(a));
        }
        if (shard.shard.count != first.shard.count) {
            differs("shard", shard_text(shard.shard), shard_text(first.shard));
            continue;
        }
        const auto [it, inserted] = by_index.emplace(shard.shard.index, &shard);
        if (!inserted) {
            problems.push_back({shard.source, 0, "shard", shard_text(shard.shard),
                                "given twice (also " + it->second->source + ")"});
        }
    }
    for (int i = 1; i <= first.shard.count && !unrelated; ++i) {
        if (by_index.count(i) == 0) {
            problems.push_back({"", 0, "merge", "",
                                "shard " + std::to_string(i) + "/"
                                    + std::to_string(first.shard.count) + " is missing"});
        }
    }
    if (!problems.empty()) {
        throw InputError(std::move(problems));
    }
    MergedBatch merged;
    merged.header = first.header;
    for (const auto& [index, shard] : by_index) {
        merged.sums.merge(shard->sums);
        merged.cells.insert(merged.cells.end(), shard->cells.begin(), shard->cells.end());
    }
    std::sort(merged.cells.begin(), merged.cells.end(),
              [](const SweepCell& a, const SweepCell& b) { return a.index < b.index; });
    return merged;
}

}  // namespace legofeup::lessons::analysis
