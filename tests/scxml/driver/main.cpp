// kse_scxml_driver: runs conformance cases (tests/conformance/cases/*.case) on the SCXML charts
// `kse export-scxml` wrote, in Qt SCXML, and compares the traces. It is the host that
// docs/adr/0038-scxml-mapping.md describes: it keeps the clock, the ten activity workers and a
// reader of the hub, hands its commands to the chart's data model through `kse_in`, and learns
// what the chart did from its <log> elements (kse.taken, kse.enter, kse.out).
//
//   kse_scxml_driver --charts <dir> [--show] <case>...
//   <dir>/<model>.scxml is the chart of a case's `model`. Prints PASS/FAIL per case (--show: the
//   trace in the case format); exit 1 when a case fails.

#include <algorithm>
#include <iostream>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include <google/protobuf/descriptor.h>
#include <google/protobuf/message.h>
#include <google/protobuf/text_format.h>
#include <google/protobuf/util/json_util.h>

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QLoggingCategory>
#include <QScxmlDataModel>
#include <QScxmlStateMachine>
#include <QXmlStreamReader>

#include <kse/messages/all.h>
#include <kse/simulation/Script.h>

namespace {

using google::protobuf::Descriptor;
using google::protobuf::FieldDescriptor;
using kse::simulation::Script;
using kse::simulation::ScriptCommand;
using kse::simulation::ScriptError;

constexpr std::size_t kWorkers = 10;

const Descriptor* MessageType(const std::string& name) {
  // naming one type of each standard file keeps the files in the program
  static const Descriptor* const kept[] = {HeadToBMessage::descriptor(), GameStateMessage::descriptor(),
                                           MotionWalkMessage::descriptor(), RobotPose::descriptor(),
                                           TimeoutMsg::descriptor()};
  (void)kept;
  return google::protobuf::DescriptorPool::generated_pool()->FindMessageTypeByName(name);
}

QJsonValue DefaultOf(const FieldDescriptor* f) {
  if (f->is_repeated()) return QJsonArray();
  switch (f->cpp_type()) {
    case FieldDescriptor::CPPTYPE_INT32: return f->default_value_int32();
    case FieldDescriptor::CPPTYPE_INT64: return QString::number(f->default_value_int64());
    case FieldDescriptor::CPPTYPE_UINT32: return static_cast<double>(f->default_value_uint32());
    case FieldDescriptor::CPPTYPE_UINT64: return QString::number(f->default_value_uint64());
    case FieldDescriptor::CPPTYPE_DOUBLE: return f->default_value_double();
    case FieldDescriptor::CPPTYPE_FLOAT: return static_cast<double>(f->default_value_float());
    case FieldDescriptor::CPPTYPE_BOOL: return f->default_value_bool();
    case FieldDescriptor::CPPTYPE_ENUM: return f->default_value_enum()->number();
    case FieldDescriptor::CPPTYPE_STRING: return QString::fromStdString(f->default_value_string());
    case FieldDescriptor::CPPTYPE_MESSAGE: return QJsonValue();
  }
  return QJsonValue();
}

// What the data model needs to read a field as the C++ accessor does: the field's proto name
// (the guards write it in lower case), its default, its message type.
void AddTypes(const Descriptor* d, QJsonObject& types) {
  const QString name = QString::fromStdString(d->name());
  if (types.contains(name)) return;
  types.insert(name, QJsonObject());
  QJsonObject fields;
  for (int i = 0; i < d->field_count(); ++i) {
    const FieldDescriptor* f = d->field(i);
    const bool message = f->cpp_type() == FieldDescriptor::CPPTYPE_MESSAGE;
    fields.insert(QString::fromStdString(f->name()).toLower(),
                  QJsonArray{QString::fromStdString(f->name()), DefaultOf(f),
                             message ? QString::fromStdString(f->message_type()->name()) : QString()});
    if (message) AddTypes(f->message_type(), types);
  }
  types.insert(name, fields);
}

QJsonObject Types() {
  QJsonObject types;
  for (const char* name : {"HeadToBMessage", "GameStateMessage", "MotionWalkMessage", "RobotPose", "TimeoutMsg"}) {
    const Descriptor* d = MessageType(name);
    const google::protobuf::FileDescriptor* file = d->file();
    for (int i = 0; i < file->message_type_count(); ++i) AddTypes(file->message_type(i), types);
    for (int j = 0; j < file->dependency_count(); ++j) {
      for (int i = 0; i < file->dependency(j)->message_type_count(); ++i) AddTypes(file->dependency(j)->message_type(i), types);
    }
  }
  return types;
}

// One message the host's reader sees.
struct Message {
  std::string type;
  QJsonObject json;
};

class Host {
 public:
  Host(const Script& script, const QString& chart, bool show) : script_(script), chart_(chart), show_(show) {}

  // Runs the script; true when every command caused the lines the case expects.
  bool Run(std::string& report) {
    machine_ = QScxmlStateMachine::fromFile(chart_);
    if (machine_ == nullptr || !machine_->parseErrors().isEmpty()) {
      report = "cannot load " + chart_.toStdString();
      if (machine_ != nullptr) {
        for (const auto& error : machine_->parseErrors()) report += "\n  " + error.toString().toStdString();
      }
      return false;
    }
    ReadLabels();
    QObject::connect(machine_, &QScxmlStateMachine::log, [this](const QString& label, const QString& msg) { Log(label, msg); });
    if (!machine_->init()) {
      report = "the chart's data model does not initialize";
      return false;
    }
    Send(QJsonObject{{"op", "types"}, {"types", Types()}});
    bool pass = true;
    for (const ScriptCommand& command : script_.commands) {
      std::vector<std::string> out;
      try {
        Execute(command, out);
      } catch (const ScriptError& e) {
        out.push_back(std::string("error: ") + e.what());
      }
      if (show_) {
        std::cout << command.text << "\n";
        for (const auto& line : out) std::cout << "  " << line << "\n";
      }
      if (out != command.output) {
        pass = false;
        report += "\n  line " + std::to_string(command.line) + " '" + command.text + "':";
        for (const auto& line : command.output) report += "\n    expected: " + line;
        for (const auto& line : out) report += "\n    actual:   " + line;
      }
    }
    delete machine_;
    return pass;
  }

 private:
  void Execute(const ScriptCommand& command, std::vector<std::string>& out) {
    const std::string& verb = command.words.at(0);
    const std::vector<std::string> args(command.words.begin() + 1, command.words.end());
    trace_ = &out;
    if (verb == "start") {
      Send(QJsonObject{{"op", "clock"}, {"now", 0}});
      handled_ = false;
      machine_->start();
      Settle();
    } else if (verb == "publish") {
      Publish(command);
    } else if (verb == "finish" || verb == "fail") {
      for (const auto& name : args) {
        if (std::none_of(running_.begin(), running_.end(), [&](const ActivityRun& r) { return r.activity == name; })) {
          throw ScriptError("'" + name + "' is not running");
        }
      }
      std::vector<std::string> ended;
      for (const auto& name : args) {
        for (auto it = running_.begin(); it != running_.end();) {
          if (it->activity == name) {
            ended.push_back(name);
            it = running_.erase(it);
          } else {
            ++it;
          }
        }
      }
      Dispatch();
      // every run ends before the engine looks again: all but the last through the inbox
      for (std::size_t i = 0; i + 1 < ended.size(); ++i) Send(QJsonObject{{"op", "done"}, {"activity", QString::fromStdString(ended[i])}});
      Submit("done.activity." + ended.back());
    } else if (verb == "advance") {
      const long long by = std::stoll(args.at(0));
      const long long target = now_ + by;
      while (!wakeups_.empty() && *wakeups_.begin() <= target) {
        now_ = std::max(now_, *wakeups_.begin());
        wakeups_.erase(wakeups_.begin(), wakeups_.upper_bound(now_));
        Send(QJsonObject{{"op", "clock"}, {"now", static_cast<double>(now_)}});
        Submit("kse.wake");
      }
      now_ = target;
      Send(QJsonObject{{"op", "clock"}, {"now", static_cast<double>(now_)}});
    } else if (verb == "active") {
      std::vector<std::pair<int, std::string>> leaves;
      for (const QString& id : machine_->activeStateNames(true)) {
        auto found = labels_.find(id);
        if (found != labels_.end()) leaves.push_back(found->second);
      }
      std::sort(leaves.begin(), leaves.end());
      std::string line = "active: ";
      for (std::size_t i = 0; i < leaves.size(); ++i) line += (i ? ", " : "") + leaves[i].second;
      out.push_back(line);
    } else if (verb == "running") {
      std::vector<std::string> names;
      for (const auto& run : running_) names.push_back(run.activity);
      std::stable_sort(names.begin(), names.end());
      std::string line;
      for (const auto& name : names) line += (line.empty() ? "" : ", ") + name;
      out.push_back("running: " + (line.empty() ? std::string("none") : line));
    } else if (verb == "read") {
      out.push_back(Read(args));
    } else {
      throw ScriptError("unknown command '" + verb + "'");
    }
  }

  // A command for the data model, applied the next time the chart runs, in order.
  void Send(QJsonObject command) {
    command.insert("seq", ++seq_);
    const int done = machine_->dataModel()->scxmlProperty("kse_done").toInt();
    pending_.erase(std::remove_if(pending_.begin(), pending_.end(), [&](const QJsonObject& c) { return c["seq"].toInt() <= done; }),
                   pending_.end());
    pending_.push_back(command);
    QJsonArray all;
    for (const auto& c : pending_) all.append(c);
    machine_->dataModel()->setScxmlProperty("kse_in", QString::fromUtf8(QJsonDocument(all).toJson(QJsonDocument::Compact)),
                                            QStringLiteral("kse_scxml_driver"));
  }

  void Submit(const std::string& event) {
    handled_ = false;
    machine_->submitEvent(QString::fromStdString(event));
    Settle();
  }

  // Until the chart has handled the last event: its macrostep is over when the event loop has it back.
  void Settle() {
    QElapsedTimer timer;
    timer.start();
    while (!handled_ && timer.elapsed() < 10000) QCoreApplication::processEvents(QEventLoop::AllEvents, 50);
    if (!handled_) throw ScriptError("the chart did not settle within 10 s");
    QCoreApplication::processEvents();
    EndStep();
    Dispatch();
  }

  // Activities begin on a free worker, each state's run after its previous one returned.
  void Dispatch() {
    for (auto it = queue_.begin(); it != queue_.end() && running_.size() < kWorkers;) {
      const bool busy = std::any_of(running_.begin(), running_.end(), [&](const ActivityRun& r) { return r.state == it->state; });
      if (busy) {
        ++it;
        continue;
      }
      running_.push_back(*it);
      Send(QJsonObject{{"op", "begin"}, {"region", QString::fromStdString(it->region)}});
      it = queue_.erase(it);
    }
  }

  void Log(const QString& label, const QString& msg) {
    if (label == "kse.taken") {
      if (!step_.empty() && entered_) EndStep();
      step_.push_back(msg.toStdString());
      entered_ = false;
    }
    if (label == "kse.event" || (label == "kse.out" && !started_)) {
      // the event submitted last (or the start) is being processed: Qt SCXML runs the whole
      // macrostep before it returns to the event loop
      started_ = true;
      handled_ = true;
    }
    if (label == "kse.enter") {
      entered_ = true;
    } else if (label == "kse.out") {
      for (const QJsonValue& note : QJsonDocument::fromJson(msg.toUtf8()).array()) {
        const QJsonObject o = note.toObject();
        if (o.contains("wakeup")) wakeups_.insert(static_cast<long long>(o["wakeup"].toDouble()));
        if (o.contains("start")) {
          queue_.push_back(ActivityRun{o["start"].toString().toStdString(), o["state"].toString().toStdString(),
                               o["region"].toString().toStdString()});
        }
        if (o.contains("publish")) {
          const QJsonObject p = o["publish"].toObject();
          Deliver(p["topic"].toString().toStdString(), p["kind"].toString().toStdString(),
                  Message{p["type"].toString().toStdString(), p["msg"].toObject()});
        }
      }
    }
  }

  void EndStep() {
    if (step_.empty()) return;
    std::string line;
    for (const auto& t : step_) line += (line.empty() ? "" : " & ") + t;
    if (trace_ != nullptr) trace_->push_back(line);
    step_.clear();
    entered_ = false;
  }

  void Publish(const ScriptCommand& command) {
    const auto& w = command.words;
    if (w.size() < 4) throw ScriptError("write: publish <topic> <State|Signal|Data> <Type> [{ fields }]");
    if (w[2] != "State" && w[2] != "Signal" && w[2] != "Data") throw ScriptError("unknown kind '" + w[2] + "'");
    const Descriptor* d = MessageType(w[3]);
    if (d == nullptr) throw ScriptError("unknown message type '" + w[3] + "'");
    std::unique_ptr<google::protobuf::Message> message(google::protobuf::MessageFactory::generated_factory()->GetPrototype(d)->New());
    const auto open = command.text.find('{');
    if (open != std::string::npos) {
      const auto close = command.text.rfind('}');
      if (close == std::string::npos || close < open ||
          !google::protobuf::TextFormat::ParseFromString(command.text.substr(open + 1, close - open - 1), message.get())) {
        throw ScriptError("cannot read the fields of " + w[3]);
      }
    }
    std::string json;
    google::protobuf::util::JsonPrintOptions options;
    options.preserve_proto_field_names = true;
    options.always_print_enums_as_ints = true;
    (void)google::protobuf::util::MessageToJsonString(*message, &json, options);
    const QJsonObject object = QJsonDocument::fromJson(QByteArray::fromStdString(json)).object();
    Deliver(w[1], w[2], Message{w[3], object});
    Send(QJsonObject{{"op", "publish"}, {"topic", QString::fromStdString(w[1])}, {"kind", QString::fromStdString(w[2])},
                     {"type", QString::fromStdString(w[3])}, {"msg", object}});
  }

  // The host's reader: a blackboard that subscribes to a topic the first time it reads it.
  void Deliver(const std::string& topic, const std::string& kind, const Message& message) {
    const std::string key = topic + "|" + message.type;
    if (kind == "State") retained_[key] = message;
    if (subscribed_.count(topic)) inbox_.push_back({key, kind, message});
  }

  std::string Read(const std::vector<std::string>& args) {
    if (args.size() != 3) throw ScriptError("write: read <topic> <State|Signal|Data> <Type>");
    const std::string& topic = args[0];
    const std::string& kind = args[1];
    const std::string& type = args[2];
    if (subscribed_.insert(topic).second) {
      for (const auto& [key, message] : retained_) {
        if (key.rfind(topic + "|", 0) == 0) inbox_.push_back({key, "State", message});
      }
    }
    for (const auto& entry : inbox_) {
      if (entry.kind == "State") state_[entry.key] = entry.message;
      else if (entry.kind == "Signal") signals_[entry.key].push_back(entry.message);
      else data_[entry.key].push_back(entry.message);
    }
    inbox_.clear();
    const std::string key = topic + "|" + type;
    std::optional<Message> found;
    if (kind == "State" && state_.count(key)) found = state_[key];
    if (kind == "Signal" && !signals_[key].empty()) {
      found = signals_[key].front();
      signals_[key].erase(signals_[key].begin());
    }
    if (kind == "Data" && !data_[key].empty()) found = data_[key].back();
    if (!found) return type + ": none";
    std::string text;
    if (type == "TimeoutMsg") {
      const QString wakeup = found->json["wakeup"].toString();
      if (!wakeup.isEmpty()) text = "wakeup at " + wakeup.toStdString() + " ms";
    } else {
      const Descriptor* d = MessageType(type);
      if (d == nullptr) throw ScriptError("unknown message type '" + type + "'");
      std::unique_ptr<google::protobuf::Message> message(google::protobuf::MessageFactory::generated_factory()->GetPrototype(d)->New());
      google::protobuf::util::JsonParseOptions options;
      options.ignore_unknown_fields = true;
      (void)google::protobuf::util::JsonStringToMessage(QJsonDocument(found->json).toJson(QJsonDocument::Compact).toStdString(),
                                                       message.get(), options);
      google::protobuf::TextFormat::Printer printer;
      printer.SetSingleLineMode(true);
      printer.PrintToString(*message, &text);
      text = kse::simulation::Trim(text);
    }
    return type + ": {" + (text.empty() ? "" : " " + text + " ") + "}";
  }

  // The KSE label of every state id, and its place in the document (the order `active` prints).
  void ReadLabels() {
    QFile file(chart_);
    if (!file.open(QIODevice::ReadOnly)) return;
    QXmlStreamReader xml(&file);
    int order = 0;
    while (!xml.atEnd()) {
      if (xml.readNext() == QXmlStreamReader::StartElement) {
        const auto attributes = xml.attributes();
        const QString label = attributes.value("http://kse/scxml/1.0", "label").toString();
        const QString id = attributes.value("id").toString();
        if (!id.isEmpty() && attributes.hasAttribute("http://kse/scxml/1.0", "type")) {
          labels_[id] = {order++, label.toStdString()};
        }
      }
    }
  }

  struct ActivityRun {
    std::string activity;
    std::string state;
    std::string region;
  };
  struct Entry {
    std::string key;
    std::string kind;
    Message message;
  };

  const Script& script_;
  QString chart_;
  bool show_;
  QScxmlStateMachine* machine_ = nullptr;
  bool handled_ = false;
  bool started_ = false;
  int seq_ = 0;
  std::vector<QJsonObject> pending_;
  long long now_ = 0;
  std::multiset<long long> wakeups_;
  std::vector<ActivityRun> running_;
  std::vector<ActivityRun> queue_;
  std::vector<std::string>* trace_ = nullptr;
  std::vector<std::string> step_;
  bool entered_ = false;
  std::map<QString, std::pair<int, std::string>> labels_;
  std::map<std::string, Message> retained_;
  std::set<std::string> subscribed_;
  std::vector<Entry> inbox_;
  std::map<std::string, Message> state_;
  std::map<std::string, std::vector<Message>> signals_;
  std::map<std::string, std::vector<Message>> data_;
};

}  // namespace

int main(int argc, char** argv) {
  QCoreApplication app(argc, argv);
  // the chart's <log> elements are the driver's input, not the user's output
  QLoggingCategory::setFilterRules(QStringLiteral("scxml.statemachine=false"));
  std::string charts;
  bool show = false;
  std::vector<std::string> cases;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--charts" && i + 1 < argc) charts = argv[++i];
    else if (arg == "--show") show = true;
    else cases.push_back(arg);
  }
  if (charts.empty() || cases.empty()) {
    std::cerr << "usage: kse_scxml_driver --charts <dir> [--show] <case>...\n";
    return 2;
  }
  int failed = 0;
  for (const std::string& file : cases) {
    Script script;
    try {
      script = kse::simulation::ReadScript(file);
    } catch (const std::exception& e) {
      std::cout << "FAIL " << file << ": " << e.what() << "\n";
      ++failed;
      continue;
    }
    Host host(script, QString::fromStdString(charts + "/" + script.model + ".scxml"), show);
    std::string report;
    bool pass = false;
    try {
      pass = host.Run(report);
    } catch (const std::exception& e) {
      report += std::string("\n  ") + e.what();
    }
    std::cout << (pass ? "PASS " : "FAIL ") << script.model << report << "\n";
    failed += pass ? 0 : 1;
  }
  std::cout << (cases.size() - failed) << " of " << cases.size() << " cases pass\n";
  return failed == 0 ? 0 : 1;
}
