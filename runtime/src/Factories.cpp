#include "statechart_engine/Factories.h"

#include <iostream>
#include <sstream>

namespace statechart_engine {

namespace detail {

void Warn(const std::string& text) {
  std::ostringstream line;
  line << "[kse] " << text << '\n';
  std::cerr << line.str() << std::flush;
}

}  // namespace detail

template class Registry<IActivity>;
template class Registry<IStatechart, kse::messaging::MessageHub&, const Options&>;

ActivityFactory& ActivityFactory::Instance() {
  static ActivityFactory instance;
  return instance;
}

Part<IActivity> ActivityFactory::PartNamed(const std::string& name) const {
  {
    std::lock_guard<std::mutex> lock(parts_mutex_);
    auto found = parts_.find(name);
    if (found != parts_.end()) {
      Part<IActivity> part;
      part.maker_ = found->second.maker_;
      return part;
    }
  }
  if (Contains(name)) {
    // registered without a registrar: made by its creator, for each statechart
    return Part<IActivity>::Created([this, name] { return Create(name); });
  }
  detail::Warn("unknown activity '" + name + "' (is its registrar linked in?)");
  return nullptr;
}

void ActivityFactory::RegisterPart(const std::string& name, Part<IActivity> part) {
  std::lock_guard<std::mutex> lock(parts_mutex_);
  parts_[name] = std::move(part);
}

StatechartFactory& StatechartFactory::Instance() {
  static StatechartFactory instance;
  return instance;
}

}  // namespace statechart_engine
