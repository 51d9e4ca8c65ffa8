#ifndef STATECHART_ENGINE_PART_H
#define STATECHART_ENGINE_PART_H

#include <cstddef>
#include <functional>
#include <memory>
#include <new>
#include <tuple>
#include <type_traits>
#include <utility>

namespace statechart_engine {

class Definition;
class ActivityFactory;

namespace detail {

class EngineCore;

/// How a Part makes its object in a statechart's block of memory (ADR 0032).
template <class I>
class PartMaker {
 public:
  PartMaker(std::size_t size, std::size_t align, std::size_t base)
      : size_(size), align_(align), base_(base) {}
  virtual ~PartMaker() = default;
  std::size_t Size() const noexcept { return size_; }
  std::size_t Align() const noexcept { return align_; }
  /// Where in the object its interface I lies, so that a statechart finds the interface of a
  /// part from the block's address and an offset alone.
  std::size_t Base() const noexcept { return base_; }
  /// Constructs the object at `where` (Size() bytes, aligned to Align()).
  virtual I* Construct(void* where) const = 0;

 private:
  std::size_t size_;
  std::size_t align_;
  std::size_t base_;
};

// Where the I in a T lies. An address stands in for an object: the conversion of a pointer to a
// base that is not virtual is arithmetic, done without one. A virtual base has no fixed place
// (the downcast below is then ill-formed), so such a T cannot be made in a block.
template <class I, class T, class = void>
struct HasFixedBase : std::false_type {};
template <class I, class T>
struct HasFixedBase<I, T, std::void_t<decltype(static_cast<T*>(std::declval<I*>()))>> : std::true_type {};

template <class I, class T>
std::size_t BaseOffset() {
  static_assert(HasFixedBase<I, T>::value,
                "a part made in a statechart's block needs its interface as a base that is not "
                "virtual; give such an object as a std::unique_ptr instead");
  alignas(T) static unsigned char stand_in[sizeof(T)];
  T* object = reinterpret_cast<T*>(stand_in);
  return static_cast<std::size_t>(reinterpret_cast<unsigned char*>(static_cast<I*>(object)) -
                                  stand_in);
}

template <class I, class T, class... A>
class ArgumentsMaker final : public PartMaker<I> {
 public:
  template <class... B>
  explicit ArgumentsMaker(B&&... arguments)
      : PartMaker<I>(sizeof(T), alignof(T), BaseOffset<I, T>()), arguments_(std::forward<B>(arguments)...) {}

  I* Construct(void* where) const override {
    return std::apply([where](const A&... arguments) -> I* { return ::new (where) T(arguments...); },
                      arguments_);
  }

 private:
  std::tuple<A...> arguments_;
};

}  // namespace detail

template <class T, class... A>
class Made;

/// What a transition or a BASIC state of a Definition gets in each statechart made from it: a
/// guard (I = ICondition), an action (IAction) or an activity (IActivity). Made anew for every
/// statechart, in the statechart's own block of memory (Make<T>(arguments...)); made anew for
/// every statechart by a function (Part::Created, the object on the heap); or one object given
/// (a std::unique_ptr), which only one statechart can take: a definition with a given object
/// makes one statechart, as a statechart that builds its own does.
template <class I>
class Part {
 public:
  Part() noexcept = default;
  Part(std::nullptr_t) noexcept {}  // NOLINT: no part, as a null std::unique_ptr was
  template <class T, class = std::enable_if_t<std::is_base_of_v<I, T>>>
  Part(std::unique_ptr<T> object)  // NOLINT: as the old signature
      : given_(std::move(object)), given_object_(given_.get()) {}

  using Creator = std::function<std::unique_ptr<I>()>;
  /// A part that `create` makes for each statechart (a null result: no part in that one).
  static Part Created(Creator create) {
    Part part;
    if (create) part.creator_ = std::make_shared<const Creator>(std::move(create));
    return part;
  }

  explicit operator bool() const noexcept {
    return given_object_ != nullptr || maker_ != nullptr || creator_ != nullptr;
  }
  bool IsGiven() const noexcept { return given_object_ != nullptr; }
  bool IsCreated() const noexcept { return creator_ != nullptr; }
  const detail::PartMaker<I>* Maker() const noexcept { return maker_.get(); }

 private:
  template <class, class...>
  friend class Made;
  friend class Definition;
  friend class ActivityFactory;
  friend class detail::EngineCore;

  // A given object belongs to the definition until the statechart that takes it moves it out
  // (so that it goes with the statechart's blackboards, which it may refer to).
  mutable std::unique_ptr<I> given_;
  I* given_object_ = nullptr;
  std::shared_ptr<const detail::PartMaker<I>> maker_;
  std::shared_ptr<const Creator> creator_;
};

/// The result of Make<T>(arguments...): turns into the Part of whichever interface T implements.
template <class T, class... A>
class Made {
 public:
  template <class... B>
  explicit Made(B&&... arguments) : arguments_(std::forward<B>(arguments)...) {}

  template <class I, class = std::enable_if_t<std::is_base_of_v<I, T>>>
  operator Part<I>() && {  // NOLINT: Make<T>() is written where a Part is expected
    Part<I> part;
    part.maker_ = std::apply(
        [](A&... arguments) {
          return std::make_shared<const detail::ArgumentsMaker<I, T, A...>>(std::move(arguments)...);
        },
        arguments_);
    return part;
  }

 private:
  std::tuple<A...> arguments_;
};

/// A part made anew for every statechart of a definition, as T(arguments...) (copies of them).
template <class T, class... A>
Made<T, std::decay_t<A>...> Make(A&&... arguments) {
  return Made<T, std::decay_t<A>...>(std::forward<A>(arguments)...);
}

}  // namespace statechart_engine

#endif
