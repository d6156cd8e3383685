#pragma once
// Shard files: one part of a Monte Carlo or a sweep split with --shard i/n (a cluster job
// array), holding everything additive about its part — per-step sums and per-run records
// for a Monte Carlo, finished cells for a sweep — under the batch's header. A merge checks
// that the shards belong together and rebuilds exactly what the unsharded command computes.
//
// Format (JSON): {"format": "legofeup-shard", "format_version": 1, "kind", "shard": {"index",
// "count"}, "configuration_hash", "header": {…}, then "run_records" and "steps" (Monte
// Carlo: exact sums as hexadecimal text, see ExactSum) or "cells" (sweep)}.

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "legofeup/lessons/analysis/analysis_tables.hpp"

namespace legofeup::lessons::analysis {

inline constexpr int kShardFormatVersion = 2;

nlohmann::json monte_carlo_shard(const BatchHeader& header, const Shard& shard,
                                 const MonteCarloSums& sums);
nlohmann::json sweep_shard(const BatchHeader& header, const Shard& shard,
                           const std::vector<SweepCell>& cells);

struct ShardFile {
    std::string source;  ///< the file, for messages
    BatchHeader header;
    Shard shard;
    MonteCarloSums sums;           ///< montecarlo
    std::vector<SweepCell> cells;  ///< sweep
};

/// Reads a shard file. Throws InputError naming the file and what is wrong with it.
ShardFile read_shard_file(const std::filesystem::path& path);
/// Parses a shard document; `source` names it in messages.
ShardFile parse_shard_file(const std::string& text, const std::string& source);

struct MergedBatch {
    BatchHeader header;
    MonteCarloSums sums;           ///< montecarlo: all runs
    std::vector<SweepCell> cells;  ///< sweep: all cells in index order
};

/// Joins shards 1/n … n/n of one batch (in any order). Throws InputError listing every
/// problem: different kinds or configurations, different n, a shard given twice, a shard
/// missing.
MergedBatch merge_shards(const std::vector<ShardFile>& shards);

}  // namespace legofeup::lessons::analysis
