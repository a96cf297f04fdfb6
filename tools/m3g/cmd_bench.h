// `m3g bench ...`: kernel benchmarks printed as tables (tools/m3g/cmd_bench.cpp).
#pragma once

namespace m3gcli {

/// Runs `m3g bench <what> [options]`; `argc`/`argv` are the arguments after
/// "bench". Returns the exit status (2 for a bad command line).
int benchCommand(int argc, const char* const* argv);

}  // namespace m3gcli
