#ifndef STATECHART_ENGINE_FACTORIES_H
#define STATECHART_ENGINE_FACTORIES_H

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>

#include "kse/messaging/MessageHub.h"
#include "statechart_engine/Interfaces.h"
#include "statechart_engine/Part.h"
#include "statechart_engine/Registry.h"
#include "statechart_engine/Statechart.h"

// Where a registrar is declared: the source file of the activity or statechart that declares it
// (a default argument evaluated at the caller), so that two registrations of one name say which
// files they come from.
#if defined(__GNUC__) || defined(__clang__) || (defined(_MSC_VER) && _MSC_VER >= 1926)
#define KSE_REGISTRAR_ORIGIN __builtin_FILE()
#else
#define KSE_REGISTRAR_ORIGIN ""
#endif

namespace statechart_engine {

// The registries are compiled once, in the library (Factories.cpp).
extern template class Registry<IActivity>;

/// Creates activities by name. Activities register themselves from a static object:
///   static statechart_engine::ActivityRegistrar<Scan> registrar("Scan");
class ActivityFactory : public Registry<IActivity> {
 public:
  /// Defined in the library, so that a process has one, however its parts are linked.
  static ActivityFactory& Instance();

  /// The activity registered under a name as the Part of a definition: made anew for every
  /// statechart of the definition, in its block. Empty (no activity: its state finishes at
  /// once), with a message on standard error, when the name is unknown, as Create() is.
  Part<IActivity> PartNamed(const std::string& name) const;
  /// Registers how a registered activity is made in a statechart's block (ActivityRegistrar).
  void RegisterPart(const std::string& name, Part<IActivity> part);

 private:
  ActivityFactory() : Registry("activity") {}

  mutable std::mutex parts_mutex_;
  std::map<std::string, Part<IActivity>> parts_;
};

template <class T>
class ActivityRegistrar {
  static_assert(std::is_base_of_v<IActivity, T>, "ActivityRegistrar<T>: T must be an IActivity");

 public:
  using Type = ActivityRegistrar<T>;  // Monas spelling: ActivityRegistrar<T>::Type temp("T");

  explicit ActivityRegistrar(const std::string& name, const char* origin = KSE_REGISTRAR_ORIGIN) {
    if (ActivityFactory::Instance().Register(name, [] { return std::unique_ptr<IActivity>(new T()); }, origin)) {
      ActivityFactory::Instance().RegisterPart(name, Make<T>());
    }
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

extern template class Registry<IStatechart, kse::messaging::MessageHub&, const Options&>;

/// Creates statecharts by name. Generated statecharts register themselves from a static object:
///   static statechart_engine::StatechartRegistrar<Goalie> registrar("Goalie");
class StatechartFactory
    : public Registry<IStatechart, kse::messaging::MessageHub&, const Options&> {
 public:
  static StatechartFactory& Instance();

  /// A new statechart, or nullptr (with a message on standard error) when the name is unknown.
  std::unique_ptr<IStatechart> Create(const std::string& name, kse::messaging::MessageHub& hub,
                                      Options options = {}) const {
    return Registry::Create(name, hub, options);
  }

 private:
  StatechartFactory() : Registry("statechart") {}
};

/// Registers T, constructible from (MessageHub&, const Options&), under a name.
template <class T>
class StatechartRegistrar {
  static_assert(std::is_base_of_v<IStatechart, T>, "StatechartRegistrar<T>: T must be an IStatechart");

 public:
  using Type = StatechartRegistrar<T>;  // Monas spelling: StatechartRegistrar<T>::Type temp("T");

  explicit StatechartRegistrar(const std::string& name, const char* origin = KSE_REGISTRAR_ORIGIN) {
    StatechartFactory::Instance().Register(
        name, [](kse::messaging::MessageHub& hub, const Options& options) {
          return std::unique_ptr<IStatechart>(new T(hub, options));
        }, origin);
  }
};

}  // namespace statechart_engine

#endif
