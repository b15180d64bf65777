#include "planner/exec_planner.h"

#include <cstdio>
#include <map>
#include <mutex>
#include <utility>

#include "planner/child_process.h"
#include "planner/planner_fault.h"

namespace mg {
namespace {

// Process-wide: the options, the hello of every command, the workers' log files.
struct Shared {
  std::mutex mutex;
  ExecOptions options;
  std::map<std::string, PlannerIdentity> identities;
  std::vector<std::string> logs;
};

Shared& shared() {
  static Shared s;
  return s;
}

ExecOptions options() {
  const std::lock_guard lock(shared().mutex);
  return shared().options;
}

double call_timeout_s() {  // read on every call: without copying the options
  const std::lock_guard lock(shared().mutex);
  return shared().options.timeout_s;
}

double start_timeout_s() {
  const std::lock_guard lock(shared().mutex);
  return shared().options.start_timeout_s;
}

std::string seconds_text(double s) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g s", s);
  return buf;
}

// One child of one command on one thread: started on demand, replaced after a fault.
class ExecSession {
 public:
  ExecSession(std::string name, std::string log_path) : name_(std::move(name)), log_path_(std::move(log_path)) {}
  ~ExecSession() { stop(); }
  ExecSession(const ExecSession&) = delete;
  ExecSession& operator=(const ExecSession&) = delete;

  const std::string& name() const { return name_; }
  const PlannerIdentity& identity() const { return identity_; }

  // Starts the child and exchanges hello within the start timeout; ExecStartError otherwise.
  void start() {
    const double timeout_s = start_timeout_s();
    try {
      child_ = std::make_unique<ChildProcess>(name_.substr(kExecPlannerPrefix.size()), log_path_);
    } catch (const ChildStartError& e) {
      throw ExecStartError("planner '" + name_ + "': " + e.what());
    }
    std::string reply;
    IoStatus status = child_->write_line(hello_request(), timeout_s);
    if (status == IoStatus::kDone) status = child_->read_line(reply, timeout_s);
    try {
      if (status == IoStatus::kDone) identity_ = parse_hello_reply(reply);
    } catch (const ProtocolError& e) {
      fail_start("answered hello wrongly: " + std::string(e.what()));
    }
    if (status == IoStatus::kTimeout) fail_start("did not answer hello within " + seconds_text(timeout_s));
    if (status == IoStatus::kClosed) fail_start(child_->exit_description() + " before answering hello");
    const std::lock_guard lock(shared().mutex);
    shared().identities[name_] = identity_;
  }

  // Before a scenario: a child that failed in an earlier one is replaced here. The scenario fails
  // (planner_exit) when the replacement cannot start.
  void ensure_started() {
    if (child_) return;
    try {
      start();
    } catch (const ExecStartError& e) {
      throw PlannerFault(kFaultExit, 0.0, std::string("could not restart: ") + e.what());
    }
  }

  // One request and its reply. Any fault ends the child and throws PlannerFault.
  std::string call(const std::string& request, const char* what, double time_s) {
    const double timeout_s = call_timeout_s();
    std::string reply;
    IoStatus status = child_->write_line(request, timeout_s);
    if (status == IoStatus::kDone) status = child_->read_line(reply, timeout_s);
    if (status == IoStatus::kTimeout)
      fail(kFaultTimeout, time_s, "did not answer " + std::string(what) + " within " + seconds_text(timeout_s));
    if (status == IoStatus::kClosed) fail(kFaultExit, time_s, child_->exit_description() + " mid-scenario");
    return reply;
  }

  [[noreturn]] void fail(const char* kind, double time_s, const std::string& what) {
    const std::string who = describe();
    child_->end(0.0);  // its state is unknown now: the next scenario starts a new one
    child_.reset();
    throw PlannerFault(kind, time_s, who + " " + what + " at t = " + seconds_text(time_s));
  }

  void stop() {
    if (!child_) return;
    child_->write_line(bye_request(), 0.1);
    child_->end(0.2);
    child_.reset();
  }

 private:
  std::string describe() const { return "planner process '" + name_ + "' (pid " + std::to_string(child_->pid()) + ")"; }

  [[noreturn]] void fail_start(const std::string& what) {
    const std::string who = describe();
    child_->end(0.0);
    child_.reset();
    throw ExecStartError(who + " " + what);
  }

  std::string name_;
  std::string log_path_;
  std::unique_ptr<ChildProcess> child_;
  PlannerIdentity identity_;
};

class ExecPlanner : public Planner {
 public:
  explicit ExecPlanner(std::shared_ptr<ExecSession> session) : session_(std::move(session)) {}
  std::string name() const override { return session_->name(); }

  PlanOutput plan(const WorldSnapshot& world) override {
    if (!reset_) {
      session_->ensure_started();
      parse_or_fail([&] { parse_ready_reply(session_->call(reset_request(*world.setup), "reset", world.time_s)); },
                    world.time_s);
      reset_ = true;
    }
    PlanOutput out;
    parse_or_fail([&] { out = parse_command_reply(session_->call(observe_request(world), "observe", world.time_s), world); },
                  world.time_s);
    // The protocol has no mode or reason of its own: a planner may name them in its annotation
    // (docs/planner_protocol.md); otherwise the mode is "command".
    if (out.mode.empty()) out.mode = "command";
    if (out.reason.empty()) out.reason = "command of " + session_->identity().name;
    return out;
  }

 private:
  template <class F>
  void parse_or_fail(F&& exchange, double time_s) {
    try {
      exchange();
    } catch (const ProtocolError& e) {
      session_->fail(kFaultReply, time_s, std::string("sent a bad reply (") + e.what() + ")");
    }
  }

  std::shared_ptr<ExecSession> session_;
  bool reset_ = false;
};

// This thread's sessions by planner name: a campaign worker is a thread, so each worker owns one
// child per command, ended when the worker (or the program) ends.
std::shared_ptr<ExecSession> session_for(const std::string& name) {
  thread_local std::map<std::string, std::shared_ptr<ExecSession>> sessions;
  std::shared_ptr<ExecSession>& s = sessions[name];
  if (s) return s;
  std::string log_path;
  {
    const std::lock_guard lock(shared().mutex);
    if (!shared().options.log_dir.empty()) {
      log_path = shared().options.log_dir + "/planner-worker-" + std::to_string(shared().logs.size()) + ".log";
      shared().logs.push_back(log_path);
    }
  }
  s = std::make_shared<ExecSession>(name, log_path);
  return s;
}

}  // namespace

bool is_exec_planner(const std::string& name) {
  return name.size() > kExecPlannerPrefix.size() && name.compare(0, kExecPlannerPrefix.size(), kExecPlannerPrefix) == 0;
}

void set_exec_options(const ExecOptions& o) {
  const std::lock_guard lock(shared().mutex);
  shared().options = o;
}

PlannerIdentity start_exec_planner(const std::string& name) {
  ExecSession probe(name, options().log_dir.empty() ? "" : options().log_dir + "/planner-start.log");
  probe.start();
  return probe.identity();
}

std::unique_ptr<Planner> make_exec_planner(const std::string& name) {
  return std::make_unique<ExecPlanner>(session_for(name));
}

std::optional<PlannerIdentity> exec_planner_identity(const std::string& name) {
  const std::lock_guard lock(shared().mutex);
  const auto it = shared().identities.find(name);
  if (it == shared().identities.end()) return std::nullopt;
  return it->second;
}

std::vector<std::string> exec_planner_logs() {
  const std::lock_guard lock(shared().mutex);
  return shared().logs;
}

}  // namespace mg
