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

  /// Registers a creator; false (and a warning naming both) when the name is taken, the
  /// first one stays and the clash is kept for Clashes(). `origin` says where the creator
  /// comes from (the registrars pass their source file), so that a clash names both.
  bool Register(const std::string& name, Creator creator, const std::string& origin = {}) {
    std::lock_guard<std::mutex> lock(mutex_);
    auto found = creators_.find(name);
    if (found != creators_.end()) {
      const std::string first = origins_[name].empty() ? "an unnamed registrar" : origins_[name];
      const std::string second = origin.empty() ? "an unnamed registrar" : origin;
      clashes_.push_back(product_ + " '" + name + "' is registered twice: by " + first + " and by " + second);
      detail::Warn(clashes_.back() + "; the first registration stays");
      return false;
    }
    creators_.emplace(name, std::move(creator));
    origins_[name] = origin;
    return true;
  }

  bool Unregister(const std::string& name) {
    std::lock_guard<std::mutex> lock(mutex_);
    origins_.erase(name);
    return creators_.erase(name) != 0;
  }

  /// Every registration refused because its name was taken, each naming both registrars. A
  /// program that plays behaviours stops on one (kse-match does): which of two activities of
  /// one name a statechart runs would depend on the order the linker put them in (ADR 0029).
  std::vector<std::string> Clashes() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return clashes_;
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
  std::map<std::string, std::string> origins_;
  std::vector<std::string> clashes_;
};

}  // namespace statechart_engine

#endif
