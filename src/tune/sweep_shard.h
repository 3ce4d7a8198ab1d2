// A sweep split into shards, for machines that render in parallel (docs/tuning.md, "Sweeps
// across machines"): `tune --sweep ... --shard i/n --out-dir DIR` renders every n-th cell
// (cells i-1, i-1+n, ...: round robin, so each shard gets a share of every axis) into DIR as one
// lossless PNG per cell plus DIR/shard.json (the sweep's axes, its cell count, which shard, and
// each cell's label and stats); `tune --merge DIR... --out SHEET.png [--csv FILE]` checks that
// the shards are of one sweep and hold every cell exactly once, and draws the sheet and CSV with
// the same code as an unsharded sweep, so the merged sheet equals it byte for byte.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "core/output_set.h"
#include "core/result.h"
#include "tune/sweep.h"

namespace ps {

// "I/N" with 1 <= I <= N <= kMaxSweepCells; errors name the text: "--shard 4/3: ...".
Result<ShardSpec> parse_shard(std::string_view text);

// The shard's cells (as render_sweep rendered them) into `dir`: cell_NNNN.png and shard.json,
// staged in `outputs` (published by the caller, all or nothing).
Status stage_shard(OutputSet& outputs, const std::string& dir, const std::vector<SweepAxis>& axes,
                   std::size_t cells_total, const ShardSpec& shard, const std::vector<SweepCell>& cells);

struct MergedSweep {
  std::vector<SweepAxis> axes;
  std::vector<SweepCell> cells;  // every cell of the sweep, in cell order
};

// Reads the shard directories. Errors: a directory without a readable shard.json
// ("DIR/shard.json: ..."), shards of different sweeps, a cell held twice or by no shard (named by
// index and label, with the shards that were given).
Result<MergedSweep> merge_shards(const std::vector<std::string>& dirs);

}  // namespace ps
