#ifndef STATECHART_ENGINE_REGISTRY_H
#define STATECHART_ENGINE_REGISTRY_H

#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <utility>
#include <vector>

namespace statechart_engine {

namespace detail {
/// "[kse] <text>" on standard error in a single write, so that lines from threads do not mix.
void Warn(const std::string& text);
}  // namespace detail

/// Creators of Product by name; Create(name, args...) hands the args to the creator. Names are
/// registered from static objects, in whatever order libraries are loaded, hence the lock.
template <class Product, class... Args>
class Registry {
 public:
  using Creator = std::function<std::unique_ptr<Product>(Args...)>;

  /// `product` names what is created, in the messages: "activity", "statechart".
  explicit Registry(std::string product) : product_(std::move(product)) {}

  /// Registers a creator; false (and a warning) when the name is taken, the first one stays.
  bool Register(const std::string& name, Creator creator) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!creators_.emplace(name, std::move(creator)).second) {
      detail::Warn(product_ + " '" + name + "' is registered twice; the first registration stays");
      return false;
    }
    return true;
  }

  bool Unregister(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    return creators_.erase(name) != 0;
  }

  /// A new product, or nullptr (with a message on standard error) when the name is unknown.
  std::unique_ptr<Product> Create(const std::string& name, Args... args) const {
    Creator creator;
    {
      // The creator runs unlocked: it may create through a registry itself.
      std::lock_guard<std::mutex> lock(mutex_);
      auto it = creators_.find(name);
      if (it != creators_.end()) {
        creator = it->second;
      }
    }
    if (!creator) {
      detail::Warn("unknown " + product_ + " '" + name + "' (is its registrar linked in?)");
      return nullptr;
    }
    return creator(std::forward<Args>(args)...);
  }

  bool Contains(const std::string& name) const {
    std::lock_guard<std::mutex> lock(mutex_);
    return creators_.count(name) != 0;
  }

  std::vector<std::string> Names() const {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<std::string> names;
    names.reserve(creators_.size());
    for (const auto& entry : creators_) {
      names.push_back(entry.first);
    }
    return names;
  }

 private:
  const std::string product_;
  mutable std::mutex mutex_;
  std::map<std::string, Creator> creators_;
};

}  // namespace statechart_engine

#endif
