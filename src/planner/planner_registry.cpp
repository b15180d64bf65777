#include "planner/planner_registry.h"

#include <mutex>
#include <stdexcept>
#include <utility>
#include <vector>

#include "planner/exec_planner.h"
#include "planner/frenet_planner.h"
#include "planner/mobil_planner.h"
#include "planner/rcpp_planner.h"
#include "planner/tripfield_planner.h"

namespace mg {
namespace {

struct Entry {
  std::string name;
  PlannerFactory factory;
};

// A vector, not a map: planner_names() lists the planners in registration order, built-ins first.
struct Registry {
  explicit Registry(std::vector<Entry> built_ins) : entries(std::move(built_ins)) {}
  std::mutex mutex;
  std::vector<Entry> entries;
};

void add(std::vector<Entry>& entries, std::string name, PlannerFactory factory) {
  if (name.empty()) throw std::invalid_argument("register_planner: empty planner name");
  if (is_exec_planner(name) || name == kExecPlannerPrefix)
    throw std::invalid_argument("register_planner: names starting with 'exec:' are exec planners (planner/exec_planner.h)");
  if (!factory) throw std::invalid_argument("register_planner: empty factory for planner '" + name + "'");
  for (const Entry& e : entries)
    if (e.name == name) throw std::invalid_argument("register_planner: planner '" + name + "' is already registered");
  entries.push_back({std::move(name), std::move(factory)});
}

// The built-ins are registered when the registry is first used, not by static objects in their
// own files: the linker drops an object file of a static library that nothing references, and a
// static registration in it with it.
std::vector<Entry> built_in_entries() {
  std::vector<Entry> entries;
  add(entries, "rcpp", [] { return std::make_unique<RcppPlanner>(false); });
  add(entries, "rcpp-coop", [] { return std::make_unique<RcppPlanner>(true); });
  add(entries, "tripfield", [] { return std::make_unique<TripFieldPlanner>(); });
  add(entries, "mobil", [] { return std::make_unique<MobilPlanner>(); });
  add(entries, "frenet", [] { return std::make_unique<FrenetPlanner>(); });
  return entries;
}

Registry& registry() {
  static Registry r(built_in_entries());
  return r;
}

}  // namespace

void register_planner(std::string name, PlannerFactory factory) {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  add(r.entries, std::move(name), std::move(factory));
}

std::unique_ptr<Planner> make_planner(const std::string& name) {
  if (is_exec_planner(name)) return make_exec_planner(name);
  Registry& r = registry();
  PlannerFactory factory;
  {
    const std::lock_guard lock(r.mutex);
    for (const Entry& e : r.entries)
      if (e.name == name) factory = e.factory;
  }
  return factory ? factory() : nullptr;  // outside the lock: a factory may be slow
}

std::vector<std::string> planner_names() {
  Registry& r = registry();
  const std::lock_guard lock(r.mutex);
  std::vector<std::string> names;
  names.reserve(r.entries.size());
  for (const Entry& e : r.entries) names.push_back(e.name);
  return names;
}

}  // namespace mg
