// cpp_planner_cli: the whole mergeguard command line with one more planner, "example-naive":
//   cpp_planner_cli fuzz --planner example-naive --runs 200 --seed 1 --jobs 1 --corpus ""
#include <mergeguard/mergeguard.h>

#include "naive_merge_planner.h"

int main(int argc, char** argv) {
  example::register_naive_merge_planner();
  return mg::cli_main(argc, argv);
}
