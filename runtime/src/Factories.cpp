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

StatechartFactory& StatechartFactory::Instance() {
  static StatechartFactory instance;
  return instance;
}

}  // namespace statechart_engine
