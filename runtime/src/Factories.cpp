#include "statechart_engine/Factories.h"

#include <iostream>
#include <sstream>
#include <utility>

namespace statechart_engine {

namespace {

void Warn(const std::string& what) {
  std::ostringstream line;
  line << "[kse] " << what << '\n';
  std::cerr << line.str() << std::flush;
}

template <class Map>
std::vector<std::string> KeysOf(const Map& map) {
  std::vector<std::string> names;
  names.reserve(map.size());
  for (const auto& entry : map) {
    names.push_back(entry.first);
  }
  return names;
}

}  // namespace

ActivityFactory& ActivityFactory::Instance() {
  static ActivityFactory instance;
  return instance;
}

bool ActivityFactory::Register(const std::string& name, Creator creator) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!creators_.emplace(name, std::move(creator)).second) {
    Warn("activity '" + name + "' is registered twice; the first registration stays");
    return false;
  }
  return true;
}

bool ActivityFactory::Unregister(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  return creators_.erase(name) != 0;
}

std::unique_ptr<IActivity> ActivityFactory::Create(const std::string& name) const {
  Creator creator;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = creators_.find(name);
    if (it != creators_.end()) {
      creator = it->second;
    }
  }
  if (!creator) {
    Warn("unknown activity '" + name + "' (is its registrar linked in?)");
    return nullptr;
  }
  return creator();
}

bool ActivityFactory::Contains(const std::string& name) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return creators_.count(name) != 0;
}

std::vector<std::string> ActivityFactory::Names() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return KeysOf(creators_);
}

StatechartFactory& StatechartFactory::Instance() {
  static StatechartFactory instance;
  return instance;
}

bool StatechartFactory::Register(const std::string& name, Creator creator) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!creators_.emplace(name, std::move(creator)).second) {
    Warn("statechart '" + name + "' is registered twice; the first registration stays");
    return false;
  }
  return true;
}

bool StatechartFactory::Unregister(const std::string& name) {
  std::lock_guard<std::mutex> lock(mutex_);
  return creators_.erase(name) != 0;
}

std::unique_ptr<IStatechart> StatechartFactory::Create(const std::string& name,
                                                       kse::messaging::MessageHub& hub,
                                                       Options options) const {
  Creator creator;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = creators_.find(name);
    if (it != creators_.end()) {
      creator = it->second;
    }
  }
  if (!creator) {
    Warn("unknown statechart '" + name + "' (is its registrar linked in?)");
    return nullptr;
  }
  return creator(hub, options);
}

bool StatechartFactory::Contains(const std::string& name) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return creators_.count(name) != 0;
}

std::vector<std::string> StatechartFactory::Names() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return KeysOf(creators_);
}

}  // namespace statechart_engine
