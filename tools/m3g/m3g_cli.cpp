// The m3g command-line tool: the commands put together on CLI11 (CliApp.h).
// Every command and option is described by `m3g --help`, `m3g CMD --help`
// or `m3g help CMD`; `m3g --version` prints the version. Exit codes
// (CliErrors.h, also in the usage): 0 success, 1 a check said no (compare,
// render --reference, bench soak), 2 usage error, 3 an input cannot be read
// or loaded, 4 an output cannot be written, 5 no Vulkan device or display,
// or rendering failed.
#include <string>
#include <vector>

#include "CliApp.h"
#include "Commands.h"
#include "DriverFilter.h"

int main(int argc, char** argv) {
    // Before any Vulkan call: GPU drivers without their device nodes are
    // not loaded (DriverFilter.h).
    m3gcli::skipDriversWithoutDevices();
    CLI::App root;
    m3gcli::CommandTable table;
    m3gcli::configureRoot(root);
    // In the order of the usage text: inspect, convert, render, check, view, measure.
    m3gcli::addInfoCommand(root, table);
    m3gcli::addConvertCommand(root, table);
    m3gcli::addRenderCommand(root, table);
    m3gcli::addCompareCommand(root, table);
    m3gcli::addExportCommand(root, table);
    m3gcli::addPickCommand(root, table);
    m3gcli::addSampleCommand(root, table);
    m3gcli::addViewCommand(root, table);
    m3gcli::addBenchCommand(root, table);
    m3gcli::addHelpCommands(root, table);
    const std::vector<std::string> args(argv + 1, argv + argc);
    return m3gcli::runCommandLine(root, table, args);
}
