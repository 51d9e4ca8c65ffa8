#include "kse/simulation/Simulation.h"

#include <algorithm>
#include <condition_variable>
#include <cstdint>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>

#include <google/protobuf/descriptor.h>
#include <google/protobuf/message.h>
#include <google/protobuf/text_format.h>

#include <kse/messages/all.h>
#include <kse/messaging/Blackboard.h>
#include <kse/messaging/Clock.h>
#include <kse/messaging/MessageHub.h>
#include <kse/robot/MonitorServer.h>
#include <statechart_engine/Factories.h>
#include <statechart_engine/Statechart.h>

namespace kse::simulation {

namespace {

using kse::messaging::Kind;
using kse::messaging::TimePoint;
using statechart_engine::State;
using statechart_engine::StateKind;

constexpr auto kActivityTimeout = std::chrono::seconds(10);

[[noreturn]] void Reject(const std::string& why) { throw ScriptError(why); }

// The runs of the scripted activities: each blocks its engine worker until the script ends it.
class Director {
 public:
  enum class Ending { Return, Throw };

  static Director& Instance() {
    static Director director;
    return director;
  }

  Ending Run(const std::string& name) {
    std::unique_lock<std::mutex> lock(mutex_);
    const std::uint64_t id = next_id_++;
    running_.emplace(id, name);
    changed_.notify_all();
    changed_.wait(lock, [&] { return endings_.count(id) != 0; });
    const Ending ending = endings_[id];
    endings_.erase(id);
    return ending;
  }

  // Ends every run of the named activity; how many there were.
  std::size_t End(const std::string& name, Ending ending) {
    std::lock_guard<std::mutex> lock(mutex_);
    std::size_t ended = 0;
    for (auto it = running_.begin(); it != running_.end();) {
      if (it->second == name) {
        endings_[it->first] = ending;
        it = running_.erase(it);
        ++ended;
      } else {
        ++it;
      }
    }
    changed_.notify_all();
    return ended;
  }

  std::vector<std::string> Running() {
    std::vector<std::string> names;
    for (const auto& run : Runs()) names.push_back(run.second);
    return names;
  }

  // The runs going on: id and activity name, by name (then by when they began).
  std::vector<std::pair<std::uint64_t, std::string>> Runs() {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::pair<std::uint64_t, std::string>> runs(running_.begin(), running_.end());
    std::stable_sort(runs.begin(), runs.end(), [](const auto& a, const auto& b) { return a.second < b.second; });
    return runs;
  }

  // Activities start on the engine's workers: waits until `count` runs have begun.
  bool AwaitStarted(std::size_t count) {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, kActivityTimeout, [&] { return running_.size() >= count; });
  }

  void EndAll() {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& entry : running_) endings_[entry.first] = Ending::Return;
    running_.clear();
    changed_.notify_all();
  }

 private:
  std::mutex mutex_;
  std::condition_variable changed_;
  std::uint64_t next_id_ = 0;
  std::map<std::uint64_t, std::string> running_;
  std::map<std::uint64_t, Ending> endings_;
};

// Like a Monas activity, it refreshes its blackboard first, then works until the script ends it.
class ScriptedActivity : public statechart_engine::IActivity {
 public:
  explicit ScriptedActivity(std::string name) : name_(std::move(name)) {}
  int Execute() override {
    _blk->ProcessMessages();
    if (Director::Instance().Run(name_) == Director::Ending::Throw) {
      throw std::runtime_error("the script failed " + name_);
    }
    return 0;
  }
  std::string GetName() override { return name_; }

 private:
  std::string name_;
};

std::optional<Kind> KindNamed(const std::string& name) {
  if (name == "State") return Kind::State;
  if (name == "Signal") return Kind::Signal;
  if (name == "Data") return Kind::Data;
  return std::nullopt;
}

// The standard messages are a static library: a .proto file that no guard of the linked
// statecharts names would be left out of the program, and its messages could not be published.
// Naming one type of each file keeps them all.
void KeepStandardMessages() {
  static const google::protobuf::Descriptor* const kept[] = {
      HeadToBMessage::descriptor(), GameStateMessage::descriptor(), MotionWalkMessage::descriptor(),
      RobotPose::descriptor()};
  (void)kept;
}

const google::protobuf::Descriptor* MessageType(const std::string& name) {
  KeepStandardMessages();
  const auto* descriptor = google::protobuf::DescriptorPool::generated_pool()->FindMessageTypeByName(name);
  if (descriptor == nullptr) Reject("unknown message type '" + name + "'");
  return descriptor;
}

}  // namespace

void RegisterScriptedActivities(const std::vector<std::string>& names) {
  for (const std::string& name : names) {
    statechart_engine::ActivityFactory::Instance().Register(
        name, [name] { return std::make_unique<ScriptedActivity>(name); });
    statechart_engine::ActivityFactory::Instance().RegisterPart(
        name, statechart_engine::Make<ScriptedActivity>(name));
  }
}

// A stand-in activity waits for the user by design: the watchdog, which reports user code that
// runs for more than a second, would report every one of them.
statechart_engine::Options EngineOptions() {
  statechart_engine::Options options;
  options.watchdog_limit = std::chrono::milliseconds(0);
  return options;
}

struct Simulation::Engine {
  explicit Engine(const std::string& model)
      : hub(clock), reader(hub, "script"),
        statechart(statechart_engine::StatechartFactory::Instance().Create(model, hub, EngineOptions())) {
    if (!statechart) Reject("no statechart '" + model + "' is linked into this simulator");
    index = std::make_unique<kse::robot::ChartIndex>(chart().GetDefinition());
  }
  statechart_engine::Statechart& chart() { return statechart->Chart(); }

  kse::messaging::ManualClock clock;
  TimePoint origin = clock.Now();
  kse::messaging::MessageHub hub;
  kse::messaging::Blackboard reader;
  std::unique_ptr<statechart_engine::IStatechart> statechart;
  std::unique_ptr<kse::robot::ChartIndex> index;
  std::set<std::string> subscribed;
};

Simulation::Simulation(const std::string& model, Options options)
    : options_(options), engine_(std::make_unique<Engine>(model)) {
  engine_->chart().SetObserver([this](const statechart_engine::TransitionSegmentBase& segment) {
    pending_.push_back(Taken{engine_->chart().StepNumber(), engine_->index->Of(segment),
                             segment.Source()->Label(), segment.Target()->Label(),
                             segment.Target()->Kind() == StateKind::Condition});
  });
}

Simulation::~Simulation() {
  Director::Instance().EndAll();
  engine_->statechart.reset();
}

void Simulation::Subscribe(const std::string& topic) {
  if (engine_->subscribed.insert(topic).second) engine_->reader.Subscribe(topic);
}

void Simulation::SetBreakpoints(std::set<std::string> states, std::set<long> transitions) {
  break_states_ = std::move(states);
  break_transitions_ = std::move(transitions);
}

std::vector<std::string> Simulation::Execute(const ScriptCommand& command) {
  executed_ = command.text;
  last_taken_.clear();
  stopped_at_.clear();
  std::vector<std::string> out;
  Run(command, out);
  return out;
}

void Simulation::Run(const ScriptCommand& command, std::vector<std::string>& out) {
  const std::string& verb = command.words.at(0);
  const std::vector<std::string> args(command.words.begin() + 1, command.words.end());
  if (verb == "start") {
    if (started_) Reject("the statechart has started already");
    engine_->chart().Activate();
    started_ = true;
  } else if (verb == "finish" || verb == "fail") {
    if (args.empty()) Reject("write: " + verb + " <activity>...");
    const auto running = Director::Instance().Running();
    for (const std::string& name : args) {
      if (std::find(running.begin(), running.end(), name) == running.end()) Reject("'" + name + "' is not running");
    }
    for (const std::string& name : args) End(command, name, verb == "fail");
  } else if (verb == "publish") {
    Publish(command);
  } else if (verb == "advance") {
    long long ms = -1;
    try {
      std::size_t used = 0;
      if (args.size() == 1) ms = std::stoll(args[0], &used);
      if (used != args[0].size()) ms = -1;
    } catch (const std::exception&) {
      ms = -1;
    }
    if (ms < 0) Reject("write: advance <milliseconds>");
    if (std::chrono::milliseconds(ms) > options_.longest_advance) {
      Reject("advance at most " + std::to_string(options_.longest_advance.count()) + " ms at once");
    }
    Advance(command, std::chrono::milliseconds(ms), out);
    return;
  } else if (verb == "active") {
    out.push_back("active: " + ActiveLeaves());
    return;
  } else if (verb == "running") {
    std::string list;
    for (const auto& name : Running()) list += (list.empty() ? "" : ", ") + name;
    out.push_back("running: " + (list.empty() ? std::string("none") : list));
    return;
  } else if (verb == "read") {
    out.push_back(Read(command));
    return;
  } else {
    Reject("unknown command '" + verb + "' (start, publish, finish, fail, advance, active, running, read)");
  }
  SettleWatched(out);
}

// What the engine does after a command: it runs if it is woken, and the activities it started
// begin on their workers.
void Simulation::Settle(std::vector<std::string>& out) {
  if (!started_) return;
  auto& chart = engine_->chart();
  chart.RunIfWoken();
  if (options_.eager) {
    for (int i = 0; i < 3; ++i) {
      chart.Wake();
      chart.RunIfWoken();
    }
  }
  // A state's activity runs at most once at a time: the runs going on are one per BASIC state
  // whose activity is running.
  std::size_t running = 0;
  for (State* state : chart.States()) {
    if (state->Kind() == StateKind::Basic && chart.IsRunning(state)) ++running;
  }
  running = std::min(running, chart.GetOptions().worker_threads);
  if (!Director::Instance().AwaitStarted(running)) throw std::runtime_error("activities did not start within 10 s");
  // a run that began in this settle began now, at this wake-up time
  std::map<std::uint64_t, std::chrono::milliseconds> started;
  for (const auto& run : Director::Instance().Runs()) {
    const auto known = run_started_.find(run.first);
    started.emplace(run.first, known == run_started_.end() ? Elapsed() : known->second);
  }
  run_started_ = std::move(started);
  Flush(out);
}

void Simulation::End(const ScriptCommand&, const std::string& name, bool fail) {
  auto& chart = engine_->chart();
  const std::size_t before = chart.RunningActivities();
  const std::size_t ended = Director::Instance().End(name, fail ? Director::Ending::Throw : Director::Ending::Return);
  const auto deadline = std::chrono::steady_clock::now() + kActivityTimeout;
  while (chart.RunningActivities() + ended > before) {
    if (std::chrono::steady_clock::now() > deadline) {
      throw std::runtime_error("the engine did not see '" + name + "' return within 10 s");
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
}

void Simulation::Publish(const ScriptCommand& command) {
  const auto& w = command.words;
  if (w.size() < 4) Reject("write: publish <topic> <State|Signal|Data> <Type> [{ fields }]");
  const auto kind = KindNamed(w[2]);
  if (!kind) Reject("unknown kind '" + w[2] + "' (State, Signal or Data)");
  const auto* descriptor = MessageType(w[3]);
  std::shared_ptr<google::protobuf::Message> message(
      google::protobuf::MessageFactory::generated_factory()->GetPrototype(descriptor)->New());
  const auto open = command.text.find('{');
  if (open != std::string::npos) {
    const auto close = command.text.rfind('}');
    if (close == std::string::npos || close < open) Reject("the fields of " + w[3] + " need a closing '}'");
    const std::string text = command.text.substr(open + 1, close - open - 1);
    if (!google::protobuf::TextFormat::ParseFromString(text, message.get())) {
      Reject("cannot read the fields '" + Trim(text) + "' of " + w[3]);
    }
  } else if (w.size() > 4) {
    Reject("the fields of " + w[3] + " go between '{' and '}'");
  }
  engine_->hub.Publish(w[1], *kind, message);
}

std::string Simulation::Read(const ScriptCommand& command) {
  const auto& w = command.words;
  if (w.size() != 4) Reject("write: read <topic> <State|Signal|Data> <Type>");
  const auto kind = KindNamed(w[2]);
  if (!kind) Reject("unknown kind '" + w[2] + "' (State, Signal or Data)");
  const auto* descriptor = MessageType(w[3]);
  Subscribe(w[1]);
  auto& reader = engine_->reader;
  reader.ProcessMessages();
  kse::messaging::Blackboard::MessagePtr message;
  if (*kind == Kind::State) message = reader.ReadStateMessage(w[1], w[3]);
  else if (*kind == Kind::Signal) message = reader.ReadSignalMessage(w[1], w[3]);
  else message = reader.ReadDataMessage(w[1], w[3]);
  if (!message) return w[3] + ": none";
  std::string text;
  if (descriptor->full_name() == "TimeoutMsg") {
    // a wake-up time relative to the start: absolute times differ from run to run
    const auto& timeout = static_cast<const TimeoutMsg&>(*message);
    if (!timeout.wakeup().empty()) {
      const auto micros = std::stoll(timeout.wakeup()) -
                          std::chrono::duration_cast<std::chrono::microseconds>(engine_->origin.time_since_epoch()).count();
      text = "wakeup at " + std::to_string(micros / 1000) + " ms";
    }
  } else {
    google::protobuf::TextFormat::Printer printer;
    printer.SetSingleLineMode(true);
    printer.PrintToString(*message, &text);
    text = Trim(text);
  }
  return w[3] + ": {" + (text.empty() ? "" : " " + text + " ") + "}";
}

// Time moves on; the engine is woken at each wake-up time on the way, as Monas' timeout workers
// woke it (eagerly: at every millisecond). A breakpoint ends the advance at the wake-up that hit it.
void Simulation::Advance(const ScriptCommand& command, std::chrono::milliseconds by, std::vector<std::string>& out) {
  auto& clock = engine_->clock;
  const TimePoint from = clock.Now();
  const TimePoint target = from + by;
  for (;;) {
    const std::optional<TimePoint> next =
        options_.eager ? std::optional<TimePoint>(clock.Now() + std::chrono::milliseconds(1)) : engine_->chart().NextWakeup();
    if (!next || *next > target) break;
    clock.Set(std::max(*next, clock.Now()));
    if (SettleWatched(out) && clock.Now() < target) {
      const auto went = std::chrono::duration_cast<std::chrono::milliseconds>(clock.Now() - from);
      executed_ = command.words[0] + " " + std::to_string(went.count());
      return;
    }
  }
  clock.Set(target);
  SettleWatched(out);
}

// Settle(), and whether it hit a breakpoint (the active states are compared only when some
// state has one).
bool Simulation::SettleWatched(std::vector<std::string>& out) {
  std::set<std::string> before;
  if (!break_states_.empty()) {
    for (auto& label : ActiveStates()) before.insert(std::move(label));
  }
  const std::size_t first = last_taken_.size();
  Settle(out);
  return HitBreakpoint(before, first);
}

// Whether the settle that began with `active_before` and `first` segments taken hit a breakpoint:
// a transition taken, or a state that became active; it is recorded in stopped_at_.
bool Simulation::HitBreakpoint(const std::set<std::string>& active_before, std::size_t first) {
  for (std::size_t i = first; i < last_taken_.size(); ++i) {
    if (break_transitions_.count(last_taken_[i].index) != 0) {
      stopped_at_ = "transition " + std::to_string(last_taken_[i].index);
      return true;
    }
  }
  if (break_states_.empty()) return false;
  for (const std::string& label : ActiveStates()) {
    if (break_states_.count(label) != 0 && active_before.count(label) == 0) {
      stopped_at_ = "state " + label;
      return true;
    }
  }
  return false;
}

// The segments taken since the last flush, one line per step: a chain through condition
// connectors as `a -> c -> b`, transitions of several regions in one step joined by ` & `.
void Simulation::Flush(std::vector<std::string>& out) {
  std::size_t i = 0;
  while (i < pending_.size()) {
    const std::size_t step = pending_[i].step;
    std::string line;
    while (i < pending_.size() && pending_[i].step == step) {
      std::string chain = pending_[i].from + " -> " + pending_[i].to;
      while (pending_[i].into_connector && i + 1 < pending_.size() && pending_[i + 1].step == step &&
             pending_[i + 1].from == pending_[i].to) {
        ++i;
        chain += " -> " + pending_[i].to;
      }
      line += (line.empty() ? "" : " & ") + chain;
      ++i;
    }
    out.push_back(line);
  }
  last_taken_.insert(last_taken_.end(), pending_.begin(), pending_.end());
  pending_.clear();
}

std::chrono::milliseconds Simulation::Elapsed() const {
  return std::chrono::duration_cast<std::chrono::milliseconds>(engine_->clock.Now() - engine_->origin);
}

std::vector<std::string> Simulation::ActiveStates() const {
  std::vector<std::string> labels;
  for (State* state : engine_->chart().States()) {
    if (engine_->chart().IsActive(state)) labels.push_back(state->Label());
  }
  return labels;
}

std::string Simulation::ActiveLeaves() const {
  std::string list;
  auto& chart = engine_->chart();
  for (State* state : chart.States()) {
    if (!chart.IsActive(state)) continue;
    bool leaf = true;
    for (State* child : state->Children()) leaf = leaf && !chart.IsActive(child);
    if (leaf) list += (list.empty() ? "" : ", ") + state->Label();
  }
  return list;
}

std::vector<std::string> Simulation::Running() const { return Director::Instance().Running(); }

std::vector<std::pair<std::string, std::chrono::milliseconds>> Simulation::RunningSince() const {
  std::vector<std::pair<std::string, std::chrono::milliseconds>> runs;
  for (const auto& run : Director::Instance().Runs()) {
    const auto known = run_started_.find(run.first);
    runs.emplace_back(run.second, known == run_started_.end() ? Elapsed() : known->second);
  }
  return runs;
}

std::vector<std::string> Simulation::StateLabels() const {
  std::vector<std::string> labels;
  for (State* state : engine_->chart().States()) labels.push_back(state->Label());
  return labels;
}

std::size_t Simulation::TransitionCount() const { return engine_->chart().GetDefinition().Transitions().size(); }

}  // namespace kse::simulation
