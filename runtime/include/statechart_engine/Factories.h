#ifndef STATECHART_ENGINE_FACTORIES_H
#define STATECHART_ENGINE_FACTORIES_H

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <type_traits>
#include <string>
#include <vector>

#include "kse/messaging/MessageHub.h"
#include "statechart_engine/Interfaces.h"
#include "statechart_engine/Statechart.h"

namespace statechart_engine {

/// Creates activities by name. Activities register themselves from a static object:
///   static statechart_engine::ActivityRegistrar<Scan> registrar("Scan");
class ActivityFactory {
 public:
  using Creator = std::function<std::unique_ptr<IActivity>()>;

  static ActivityFactory& Instance();

  /// Registers a creator; false (and a warning) when the name is taken, the first one stays.
  bool Register(const std::string& name, Creator creator);
  bool Unregister(const std::string& name);
  /// A new activity, or nullptr (with a message on standard error) when the name is unknown.
  std::unique_ptr<IActivity> Create(const std::string& name) const;
  bool Contains(const std::string& name) const;
  std::vector<std::string> Names() const;

 private:
  ActivityFactory() = default;
  mutable std::mutex mutex_;
  std::map<std::string, Creator> creators_;
};

template <class T>
class ActivityRegistrar {
  static_assert(std::is_base_of_v<IActivity, T>, "ActivityRegistrar<T>: T must be an IActivity");

 public:
  using Type = ActivityRegistrar<T>;  // Monas spelling: ActivityRegistrar<T>::Type temp("T");

  explicit ActivityRegistrar(const std::string& name) {
    ActivityFactory::Instance().Register(name, [] { return std::unique_ptr<IActivity>(new T()); });
  }
};

/// What generated statechart classes implement: a wrapper that owns a Statechart.
class IStatechart {
 public:
  virtual ~IStatechart();
  virtual void Start() = 0;
  virtual void Stop() = 0;
  virtual Statechart& Chart() = 0;
};

/// Creates statecharts by name. Generated statecharts register themselves from a static object:
///   static statechart_engine::StatechartRegistrar<Goalie> registrar("Goalie");
class StatechartFactory {
 public:
  using Creator =
      std::function<std::unique_ptr<IStatechart>(kse::messaging::MessageHub&, const Options&)>;

  static StatechartFactory& Instance();

  bool Register(const std::string& name, Creator creator);
  bool Unregister(const std::string& name);
  /// A new statechart, or nullptr (with a message on standard error) when the name is unknown.
  std::unique_ptr<IStatechart> Create(const std::string& name, kse::messaging::MessageHub& hub,
                                      Options options = {}) const;
  bool Contains(const std::string& name) const;
  std::vector<std::string> Names() const;

 private:
  StatechartFactory() = default;
  mutable std::mutex mutex_;
  std::map<std::string, Creator> creators_;
};

/// Registers T, constructible from (MessageHub&, const Options&), under a name.
template <class T>
class StatechartRegistrar {
  static_assert(std::is_base_of_v<IStatechart, T>, "StatechartRegistrar<T>: T must be an IStatechart");

 public:
  using Type = StatechartRegistrar<T>;  // Monas spelling: StatechartRegistrar<T>::Type temp("T");

  explicit StatechartRegistrar(const std::string& name) {
    StatechartFactory::Instance().Register(
        name, [](kse::messaging::MessageHub& hub, const Options& options) {
          return std::unique_ptr<IStatechart>(new T(hub, options));
        });
  }
};

}  // namespace statechart_engine

#endif
