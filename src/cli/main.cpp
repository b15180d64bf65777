// mergeguard: formal rule checking and scenario fuzzing for autonomous lane merges. The command
// line itself is a library function (cli/cli_main.h) so that programs adding their own planners
// run the same one.
#include "cli/cli_main.h"

int main(int argc, char** argv) { return mg::cli_main(argc, argv); }
