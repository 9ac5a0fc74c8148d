// The chart of `eyestream bench`: error against reference (p99 CIEDE2000)
// over time per frame, one line per frame size through its presets: the
// speed/accuracy trade at a glance.
#pragma once

#include <string>
#include <vector>

#include "pipeline/bench/bench_command.hpp"

namespace eyestream::pipeline {

// Writes the PNG (staged: it appears only when complete). Rows without an
// error against the reference (other than the reference itself) are left out.
void draw_bench_chart(const std::vector<BenchRow>& rows, const std::string& path);

}  // namespace eyestream::pipeline
