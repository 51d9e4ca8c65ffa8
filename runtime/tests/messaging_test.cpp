// kse::messaging: clocks, the hub, blackboards as snapshots (ProcessMessages), the State / Signal /
// Data semantics, and wake-up times.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <malloc.h>

#include <atomic>
#include <new>
#include <thread>

#include <google/protobuf/dynamic_message.h>

#include "kse/messaging/Recycled.h"

#include "test_support.h"

namespace kse_test {
namespace {

using kse::messaging::Blackboard;
using kse::messaging::Kind;
using kse::messaging::SteadyClock;
using kse::messaging::TimePoint;
using std::chrono::milliseconds;
using ::testing::ElementsAre;

std::shared_ptr<HeadToBMessage> Head(int ballfound) {
  auto message = std::make_shared<HeadToBMessage>();
  message->set_ballfound(ballfound);
  return message;
}

class Messaging : public ::testing::Test {
 protected:
  ManualClock clock{TimePoint(std::chrono::seconds(100))};
  MessageHub hub{clock};
};

TEST(Clocks, ManualClockMovesOnlyWhenTold) {
  ManualClock clock;
  EXPECT_EQ(clock.Now(), TimePoint{});
  clock.Advance(milliseconds(250));
  EXPECT_EQ(clock.Now(), TimePoint(milliseconds(250)));
  clock.Set(TimePoint(std::chrono::seconds(3)));
  EXPECT_EQ(clock.Now(), TimePoint(std::chrono::seconds(3)));
}

TEST(Clocks, SteadyClockFollowsRealTime) {
  const auto before = std::chrono::steady_clock::now();
  const auto now = SteadyClock::Instance().Now();
  EXPECT_GE(now, before);
  EXPECT_EQ(&SteadyClock::Instance(), &SteadyClock::Instance());
  EXPECT_STREQ(kse::messaging::ToString(Kind::Signal), "Signal");
  EXPECT_STREQ(kse::messaging::ToString(Kind::State), "State");
  EXPECT_STREQ(kse::messaging::ToString(Kind::Data), "Data");
}

TEST_F(Messaging, StateKeepsTheLastValue) {
  Blackboard board(hub);
  board.Subscribe("behavior");
  EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior"), nullptr);
  hub.Publish("behavior", Kind::State, Head(1));
  hub.Publish("behavior", Kind::State, Head(2));
  board.ProcessMessages();
  auto state = board.ReadState<HeadToBMessage>("behavior");
  ASSERT_NE(state, nullptr);
  EXPECT_EQ(state->ballfound(), 2);
  // Reading does not consume.
  EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior")->ballfound(), 2);
}

TEST_F(Messaging, MessagesAreKeyedByTopicAndType) {
  Blackboard board(hub);
  board.Subscribe("behavior");
  board.Subscribe("other");
  auto fall = std::make_shared<FallMessage>();
  fall->set_fall(-1);
  hub.Publish("behavior", Kind::State, Head(3));
  hub.Publish("behavior", Kind::State, fall);
  hub.Publish("other", Kind::State, Head(4));
  board.ProcessMessages();
  EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior")->ballfound(), 3);
  EXPECT_EQ(board.ReadState<FallMessage>("behavior")->fall(), -1);
  EXPECT_EQ(board.ReadState<HeadToBMessage>("other")->ballfound(), 4);
  EXPECT_EQ(board.ReadState<FallMessage>("other"), nullptr);
}

TEST_F(Messaging, KindsAreKeptApart) {
  Blackboard board(hub);
  board.Subscribe("behavior");
  hub.Publish("behavior", Kind::Signal, Head(1));
  board.ProcessMessages();
  EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior"), nullptr);
  EXPECT_EQ(board.ReadData<HeadToBMessage>("behavior"), nullptr);
  EXPECT_NE(board.ReadSignal<HeadToBMessage>("behavior"), nullptr);
}

TEST_F(Messaging, OnlySubscribedTopicsAreDelivered) {
  Blackboard board(hub);
  board.Subscribe("behavior");
  board.Subscribe("behavior");  // idempotent
  EXPECT_EQ(hub.SubscriberCount("behavior"), 1U);
  hub.Publish("vision", Kind::Signal, Head(1));
  hub.Publish("vision", Kind::State, Head(1));
  board.ProcessMessages();
  EXPECT_EQ(board.PendingMessages(), 0U);
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>("vision"), nullptr);
  EXPECT_EQ(board.ReadState<HeadToBMessage>("vision"), nullptr);
  EXPECT_TRUE(board.IsSubscribed("behavior"));
  EXPECT_FALSE(board.IsSubscribed("vision"));
}

TEST_F(Messaging, LateSubscriberStartsWithTheCurrentState) {
  hub.Publish("worldstate", Kind::State, Head(5));
  hub.Publish("worldstate", Kind::Signal, Head(6));
  Blackboard board(hub);
  board.Subscribe("worldstate");
  board.ProcessMessages();
  ASSERT_NE(board.ReadState<HeadToBMessage>("worldstate"), nullptr);
  EXPECT_EQ(board.ReadState<HeadToBMessage>("worldstate")->ballfound(), 5);
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>("worldstate"), nullptr) << "signals are not retained";
}

TEST_F(Messaging, DeliveriesFollowSubscribersThatComeAndGo) {
  // The hub remembers where each type of a topic goes in each subscriber: a board that comes,
  // one that goes (and another made where it was) and a second type on the topic must each get
  // exactly what they would have got from a lookup per message.
  auto first = std::make_unique<Blackboard>(hub, "first");
  first->Subscribe("behavior");
  hub.Publish("behavior", Kind::Signal, Head(1));
  hub.Publish("behavior", Kind::State, Head(2));
  Blackboard second(hub, "second");
  second.Subscribe("behavior");
  hub.Publish("behavior", Kind::Signal, Head(3));
  auto position = std::make_shared<PositionMessage>();
  position->set_posx(4.0f);
  hub.Publish("behavior", Kind::State, position);
  first->ProcessMessages();
  second.ProcessMessages();
  EXPECT_EQ(first->ReadSignal<HeadToBMessage>("behavior")->ballfound(), 1);
  EXPECT_EQ(first->ReadSignal<HeadToBMessage>("behavior")->ballfound(), 3);
  EXPECT_EQ(first->ReadState<HeadToBMessage>("behavior")->ballfound(), 2);
  EXPECT_FLOAT_EQ(first->ReadState<PositionMessage>("behavior")->posx(), 4.0f);
  EXPECT_EQ(second.ReadSignal<HeadToBMessage>("behavior")->ballfound(), 3) << "subscribed after the first signal";
  EXPECT_EQ(second.ReadSignal<HeadToBMessage>("behavior"), nullptr);
  EXPECT_EQ(second.ReadState<HeadToBMessage>("behavior")->ballfound(), 2) << "the retained state";
  EXPECT_FLOAT_EQ(second.ReadState<PositionMessage>("behavior")->posx(), 4.0f);

  first.reset();  // leaves the hub; a new board may well take its place in memory
  auto third = std::make_unique<Blackboard>(hub, "third");
  third->Subscribe("behavior");
  hub.Publish("behavior", Kind::Signal, Head(5));
  second.ProcessMessages();
  third->ProcessMessages();
  EXPECT_EQ(second.ReadSignal<HeadToBMessage>("behavior")->ballfound(), 5);
  EXPECT_EQ(third->ReadSignal<HeadToBMessage>("behavior")->ballfound(), 5);
  EXPECT_EQ(third->ReadSignal<HeadToBMessage>("behavior"), nullptr);
  EXPECT_EQ(third->ReadState<HeadToBMessage>("behavior")->ballfound(), 2);
  EXPECT_EQ(hub.SubscriberCount("behavior"), 2U);

  // a board publishing on the topic does not get its own message back, the others do
  third->Publish("behavior", Kind::Signal, *Head(6));
  EXPECT_EQ(third->PendingMessages(), 0U);
  EXPECT_EQ(second.PendingMessages(), 1U);
  second.ProcessMessages();
  EXPECT_EQ(second.ReadSignal<HeadToBMessage>("behavior")->ballfound(), 6);
}

TEST_F(Messaging, SignalsAreReadOnceInOrder) {
  Blackboard board(hub);
  board.Subscribe("behavior");
  hub.Publish("behavior", Kind::Signal, Head(1));
  hub.Publish("behavior", Kind::Signal, Head(2));
  board.ProcessMessages();
  EXPECT_EQ(board.PendingSignals("behavior", "HeadToBMessage"), 2U);
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>("behavior")->ballfound(), 1);
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>("behavior")->ballfound(), 2);
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>("behavior"), nullptr);
}

TEST_F(Messaging, EachBlackboardSeesASignalOnce) {
  Blackboard one(hub, "one");
  Blackboard two(hub, "two");
  one.Subscribe("behavior");
  two.Subscribe("behavior");
  hub.Publish("behavior", Kind::Signal, Head(9));
  one.ProcessMessages();
  two.ProcessMessages();
  EXPECT_NE(one.ReadSignal<HeadToBMessage>("behavior"), nullptr);
  EXPECT_EQ(one.ReadSignal<HeadToBMessage>("behavior"), nullptr);
  EXPECT_NE(two.ReadSignal<HeadToBMessage>("behavior"), nullptr);
  EXPECT_EQ(two.ReadSignal<HeadToBMessage>("behavior"), nullptr);
}

TEST_F(Messaging, SignalQueueIsBounded) {
  Blackboard board(hub);
  board.Subscribe("behavior");
  for (std::size_t i = 0; i < Blackboard::kSignalQueueLimit + 5; ++i) {
    hub.Publish("behavior", Kind::Signal, Head(static_cast<int>(i)));
  }
  EXPECT_EQ(board.PendingMessages(), Blackboard::kSignalQueueLimit) << "the inbox is bounded too";
  board.ProcessMessages();
  EXPECT_EQ(board.PendingSignals("behavior", "HeadToBMessage"), Blackboard::kSignalQueueLimit);
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>("behavior")->ballfound(), 5) << "oldest dropped";
}

TEST_F(Messaging, DataKeepsATimeStampedBoundedHistory) {
  Blackboard board(hub);
  board.Subscribe("worldstate");
  EXPECT_EQ(board.ReadData<HeadToBMessage>("worldstate"), nullptr);
  const TimePoint begin = clock.Now();
  for (int i = 0; i < 150; ++i) {
    hub.Publish("worldstate", Kind::Data, Head(i));
    clock.Advance(milliseconds(10));
  }
  board.ProcessMessages();
  EXPECT_EQ(board.ReadData<HeadToBMessage>("worldstate")->ballfound(), 149);
  auto all = board.ReadDataHistory<HeadToBMessage>("worldstate", begin);
  ASSERT_EQ(all.size(), Blackboard::kDataHistoryLimit);
  EXPECT_EQ(all.front().message->ballfound(), 50);
  EXPECT_EQ(all.back().message->ballfound(), 149);
  EXPECT_EQ(all.front().time, begin + milliseconds(500));
  // Since a time: entries stamped at or after it, oldest first.
  auto recent = board.ReadDataHistory<HeadToBMessage>("worldstate", begin + milliseconds(1470));
  ASSERT_EQ(recent.size(), 3U);
  EXPECT_EQ(recent[0].message->ballfound(), 147);
  EXPECT_EQ(recent[2].message->ballfound(), 149);
  EXPECT_EQ(recent[2].time, begin + milliseconds(1490));
  // Reading does not consume.
  EXPECT_EQ(board.ReadData<HeadToBMessage>("worldstate")->ballfound(), 149);
}

TEST_F(Messaging, BlackboardPublishCopiesShowsAtOnceAndGoesThroughTheHub) {
  Blackboard writer(hub, "writer");
  Blackboard reader(hub, "reader");
  reader.Subscribe("behavior");
  HeadToBMessage message;
  message.set_ballfound(1);
  writer.Publish("behavior", Kind::State, message);
  message.set_ballfound(2);  // the published copy does not change
  EXPECT_EQ(writer.ReadState<HeadToBMessage>("behavior")->ballfound(), 1)
      << "the publisher sees its own message at once, subscribed or not";
  EXPECT_EQ(reader.ReadState<HeadToBMessage>("behavior"), nullptr) << "others at their next refresh";
  reader.ProcessMessages();
  EXPECT_EQ(reader.ReadState<HeadToBMessage>("behavior")->ballfound(), 1);
  EXPECT_EQ(hub.PublishedCount(), 1U);
}

TEST_F(Messaging, ABlackboardIsASnapshotUntilItProcessesItsMessages) {
  Blackboard board(hub);
  board.Subscribe("behavior");
  hub.Publish("behavior", Kind::State, Head(1));
  hub.Publish("behavior", Kind::Signal, Head(2));
  hub.Publish("behavior", Kind::Data, Head(3));
  EXPECT_EQ(board.PendingMessages(), 3U);
  EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior"), nullptr);
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>("behavior"), nullptr);
  EXPECT_EQ(board.ReadData<HeadToBMessage>("behavior"), nullptr);
  board.ProcessMessages();
  EXPECT_EQ(board.PendingMessages(), 0U);
  EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior")->ballfound(), 1);
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>("behavior")->ballfound(), 2);
  EXPECT_EQ(board.ReadData<HeadToBMessage>("behavior")->ballfound(), 3);
  // A newer State waits in the inbox; the snapshot keeps the old one until the next refresh.
  hub.Publish("behavior", Kind::State, Head(4));
  EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior")->ballfound(), 1);
  board.ProcessMessages();
  EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior")->ballfound(), 4);
}

TEST_F(Messaging, APublisherNeverGetsItsOwnMessageBack) {
  Blackboard board(hub, "board");
  board.Subscribe("behavior");
  HeadToBMessage mine;
  mine.set_ballfound(7);
  board.Publish("behavior", Kind::Signal, mine);
  board.Publish("behavior", Kind::State, mine);
  EXPECT_EQ(board.PendingMessages(), 0U) << "no echo through the hub";
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>("behavior")->ballfound(), 7);
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>("behavior"), nullptr) << "seen once";
  // Nor as retained state when it subscribes to a topic it published on before.
  board.Publish("motion", Kind::State, mine);
  board.Subscribe("motion");
  EXPECT_EQ(board.PendingMessages(), 0U);
}

TEST_F(Messaging, WakeupTimesAreTakenOnceDue) {
  Blackboard board(hub);
  EXPECT_FALSE(board.NextWakeup().has_value());
  EXPECT_FALSE(board.TakeDueWakeups(clock.Now()));
  board.ScheduleWakeup(clock.Now() + milliseconds(250));
  board.ScheduleWakeup(clock.Now() + milliseconds(100));
  board.ScheduleWakeup(clock.Now() + milliseconds(100));
  EXPECT_EQ(*board.NextWakeup(), clock.Now() + milliseconds(100));
  EXPECT_FALSE(board.TakeDueWakeups(clock.Now() + milliseconds(99)));
  EXPECT_TRUE(board.TakeDueWakeups(clock.Now() + milliseconds(100))) << "both at 100 ms, taken together";
  EXPECT_EQ(*board.NextWakeup(), clock.Now() + milliseconds(250));
  EXPECT_FALSE(board.TakeDueWakeups(clock.Now() + milliseconds(100)));
  EXPECT_TRUE(board.TakeDueWakeups(clock.Now() + milliseconds(1000)));
  EXPECT_FALSE(board.NextWakeup().has_value());
}

TEST_F(Messaging, NullMessagesAreIgnored) {
  Blackboard board(hub);
  board.Subscribe("behavior");
  hub.Publish("behavior", Kind::State, nullptr);
  EXPECT_EQ(hub.PublishedCount(), 0U);
}

TEST_F(Messaging, ListenersAreCalledAfterEveryPublishUntilRemoved) {
  Blackboard board(hub);
  board.Subscribe("behavior");
  int calls = 0;
  bool delivered = false;
  auto id = hub.AddListener([&] {
    ++calls;
    delivered = board.PendingMessages() != 0;
  });
  hub.Publish("behavior", Kind::State, Head(1));
  hub.Publish("unrelated", Kind::Signal, Head(1));
  EXPECT_EQ(calls, 2);
  EXPECT_TRUE(delivered) << "listeners run after delivery";
  hub.RemoveListener(id);
  hub.Publish("behavior", Kind::State, Head(1));
  EXPECT_EQ(calls, 2);
}

TEST_F(Messaging, DestroyedBlackboardsUnsubscribe) {
  {
    Blackboard board(hub);
    board.Subscribe("behavior");
    EXPECT_EQ(hub.SubscriberCount("behavior"), 1U);
  }
  EXPECT_EQ(hub.SubscriberCount("behavior"), 0U);
  hub.Publish("behavior", Kind::Signal, Head(1));  // must not touch the destroyed board
}

TEST_F(Messaging, ConcurrentPublishersAndReaders) {
  Blackboard board(hub);
  board.Subscribe("worldstate");
  constexpr int kThreads = 4;
  constexpr int kEach = 250;  // all signals fit in one queue (kSignalQueueLimit)
  std::atomic<bool> done{false};
  std::atomic<int> signals{0};
  std::thread reader([&] {
    while (!done.load()) {
      if (board.ReadSignal<HeadToBMessage>("worldstate")) ++signals;
      board.ReadState<HeadToBMessage>("worldstate");
      board.ReadDataHistory<HeadToBMessage>("worldstate", TimePoint{});
      board.ProcessMessages();
      board.NextWakeup();
    }
  });
  std::vector<std::thread> writers;
  for (int t = 0; t < kThreads; ++t) {
    writers.emplace_back([&, t] {
      for (int i = 0; i < kEach; ++i) {
        hub.Publish("worldstate", Kind::Signal, Head(i));
        hub.Publish("worldstate", Kind::State, Head(i));
        hub.Publish("worldstate", Kind::Data, Head(i));
        if (i % 50 == 0) board.ScheduleWakeup(clock.Now() + milliseconds(i));
      }
    });
  }
  for (auto& writer : writers) writer.join();
  done.store(true);
  reader.join();
  board.ProcessMessages();
  while (board.ReadSignal<HeadToBMessage>("worldstate")) ++signals;
  EXPECT_EQ(signals.load(), kThreads * kEach);
  EXPECT_EQ(hub.PublishedCount(), static_cast<std::size_t>(3 * kThreads * kEach));
}

TEST_F(Messaging, KeysThatBeginAlikeStayApart) {
  // A lookup first compares the first 16 bytes of topics and 24 of type names with their
  // lengths; longer keys that agree there must still be told apart by the whole string.
  Blackboard board(hub);
  const std::string ball = "robot/behaviour/ball";
  const std::string goal = "robot/behaviour/goal";
  const std::string longer = "robot/behaviour/goal/near";
  for (const auto* topic : {&ball, &goal, &longer}) board.Subscribe(*topic);
  board.Subscribe("b");
  hub.Publish(ball, Kind::State, Head(1));
  hub.Publish(goal, Kind::State, Head(2));
  hub.Publish(longer, Kind::State, Head(3));
  hub.Publish("b", Kind::State, Head(4));
  hub.Publish(goal, Kind::Signal, Head(5));
  hub.Publish(ball, Kind::Data, Head(6));
  board.ProcessMessages();
  EXPECT_EQ(board.ReadState<HeadToBMessage>(ball)->ballfound(), 1);
  EXPECT_EQ(board.ReadState<HeadToBMessage>(goal)->ballfound(), 2);
  EXPECT_EQ(board.ReadState<HeadToBMessage>(longer)->ballfound(), 3);
  EXPECT_EQ(board.ReadState<HeadToBMessage>("b")->ballfound(), 4);
  EXPECT_EQ(board.ReadState<HeadToBMessage>("robot/behaviour/gold"), nullptr);
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>(ball), nullptr);
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>(goal)->ballfound(), 5);
  EXPECT_EQ(board.ReadData<HeadToBMessage>(ball)->ballfound(), 6);
  EXPECT_EQ(board.ReadData<HeadToBMessage>(goal), nullptr);
  EXPECT_EQ(board.PendingSignals(goal, "HeadToBMessage"), 0U);
  EXPECT_EQ(board.ReadStateMessage(longer, "HeadToBMessage") != nullptr, true);
  EXPECT_EQ(board.ReadStateMessage(longer, "HeadToBMessag"), nullptr) << "a type name is matched whole";
}

TEST_F(Messaging, AMessageOfAnotherClassWithTheSameNameIsNotReadAsThatClass) {
  // Typed reads skip dynamic_cast for a message of exactly the class asked for; a dynamic
  // message of the same protobuf type is kept under the same key but is not that class.
  google::protobuf::DynamicMessageFactory factory;
  std::shared_ptr<google::protobuf::Message> dynamic(factory.GetPrototype(HeadToBMessage::descriptor())->New());
  Blackboard board(hub);
  board.Subscribe("behavior");
  hub.Publish("behavior", Kind::State, dynamic);
  board.ProcessMessages();
  EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior"), nullptr);
  EXPECT_EQ(board.ReadStateMessage("behavior", "HeadToBMessage"), dynamic);
  hub.Publish("behavior", Kind::State, std::shared_ptr<const HeadToBMessage>(Head(7)));
  board.ProcessMessages();
  EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior")->ballfound(), 7) << "the same key, replaced";
}

TEST_F(Messaging, AReaderBoundBeforeAnyMessageReadsWhatTheBlackboardsReadsWould) {
  // Generated guards bind a Reader in UserInit(), before anything is published: it must see the
  // same snapshot as the string-keyed reads, kind by kind, and keep other keys apart.
  Blackboard board(hub);
  board.Subscribe("behavior");
  kse::messaging::Reader<HeadToBMessage> state(board, "behavior");
  kse::messaging::Reader<HeadToBMessage> signal(board, "worldstate");
  kse::messaging::Reader<HeadToBMessage> data(board, "other");
  kse::messaging::Reader<PositionMessage> other_type(board, "behavior");
  EXPECT_EQ(state.ReadState(), nullptr);

  hub.Publish("behavior", Kind::State, Head(1));
  EXPECT_EQ(state.ReadState(), nullptr) << "a snapshot until ProcessMessages()";
  board.ProcessMessages();
  ASSERT_NE(state.ReadState(), nullptr);
  EXPECT_EQ(state.ReadState(), board.ReadState<HeadToBMessage>("behavior"));
  EXPECT_EQ(state.ReadState()->ballfound(), 1);
  EXPECT_EQ(other_type.ReadState(), nullptr);
  EXPECT_EQ(state.ReadSignal(), nullptr) << "a State message is not a signal";

  board.Publish("worldstate", Kind::Signal, *Head(2));
  board.Publish("worldstate", Kind::Signal, *Head(3));
  EXPECT_EQ(signal.ReadSignal()->ballfound(), 2) << "the own signal, at once, consumed";
  EXPECT_EQ(board.ReadSignal<HeadToBMessage>("worldstate")->ballfound(), 3);
  EXPECT_EQ(signal.ReadSignal(), nullptr);

  board.Publish("other", Kind::Data, *Head(4));
  board.Publish("other", Kind::Data, *Head(5));
  EXPECT_EQ(data.ReadData()->ballfound(), 5);
  EXPECT_EQ(data.ReadData()->ballfound(), 5) << "reading Data does not consume";
  EXPECT_EQ(board.ReadDataHistory<HeadToBMessage>("other", TimePoint{}).size(), 2u);
}

TEST_F(Messaging, AReaderReadBeforeItIsBoundSaysSo) {
  kse::messaging::Reader<HeadToBMessage> reader;
  EXPECT_FALSE(reader.IsBound());
  try {
    (void)reader.ReadState();
    FAIL() << "an unbound reader read";
  } catch (const std::logic_error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("Reader<HeadToBMessage> read before Bind"));
  }
}

TEST_F(Messaging, WakeupsScheduledMeanwhileOnAnotherThreadAreTakenLater) {
  // TakeDueWakeups answers "none due yet" without the lock; what another thread schedules in
  // the meantime must be taken by a later call, never lost.
  Blackboard board(hub);
  constexpr int kWakeups = 2000;
  std::atomic<int> taken{0};
  std::atomic<bool> done{false};
  std::thread taker([&] {
    while (!done.load() || board.NextWakeup().has_value()) {
      if (board.TakeDueWakeups(clock.Now())) ++taken;
    }
  });
  for (int i = 0; i < kWakeups; ++i) {
    board.ScheduleWakeup(clock.Now() - milliseconds(i % 3));  // due at once
    if (i % 100 == 0) std::this_thread::yield();
  }
  done.store(true);
  taker.join();
  EXPECT_FALSE(board.NextWakeup().has_value());
  EXPECT_FALSE(board.TakeDueWakeups(clock.Now()));
  EXPECT_GE(taken.load(), 1);
}

TEST_F(Messaging, AnUnusedBlackboardIsThirtyTwoBytesAndTakesNothingFromTheHeap) {
  // Every statechart has a root blackboard and every AND region one more; most never hold a
  // message. 100 of them, named like charts and regions, made where no allocation hides.
  EXPECT_LE(sizeof(Blackboard), 32U);
  constexpr int kBoards = 100;
  alignas(Blackboard) static unsigned char storage[kBoards][sizeof(Blackboard)];
  const std::string name = "Node_ChaseBall";  // 14 characters, kept in place
  (void)Blackboard::TypeName<HeadToBMessage>();  // the type's name, looked up once per process
  const std::size_t before = mallinfo2().uordblks;
  for (auto& place : storage) new (place) Blackboard(hub, name);
  const std::size_t after = mallinfo2().uordblks;
  EXPECT_EQ(after, before) << "unused blackboards took heap memory";
  auto& board = *std::launder(reinterpret_cast<Blackboard*>(storage[0]));
  // what an unused blackboard answers, without making anything
  const bool subscribed = board.IsSubscribed("behavior");
  const bool state = board.ReadState<HeadToBMessage>("behavior") != nullptr;
  const bool signal = board.ReadSignal<HeadToBMessage>("behavior") != nullptr;
  const bool data = board.ReadData<HeadToBMessage>("behavior") != nullptr;
  const std::size_t pending = board.PendingMessages();
  const bool wakeup = board.NextWakeup().has_value();
  const bool due = board.TakeDueWakeups(clock.Now());
  board.ProcessMessages();
  EXPECT_EQ(mallinfo2().uordblks, after) << "reading an unused blackboard took heap memory";
  EXPECT_FALSE(subscribed);
  EXPECT_FALSE(state);
  EXPECT_FALSE(signal);
  EXPECT_FALSE(data);
  EXPECT_EQ(pending, 0U);
  EXPECT_FALSE(wakeup);
  EXPECT_FALSE(due);
  EXPECT_TRUE(board.ReadDataHistory<HeadToBMessage>("behavior", TimePoint{}).empty());
  EXPECT_EQ(board.PendingSignals("behavior", "HeadToBMessage"), 0U);
  EXPECT_EQ(board.Name(), name);
  for (auto& place : storage) std::launder(reinterpret_cast<Blackboard*>(place))->~Blackboard();
}

TEST_F(Messaging, ABlackboardWithALongNameKeepsIt) {
  const std::string name = "Node_WaitForTheKickOffOfTheOtherTeam";
  Blackboard board(hub, name);
  EXPECT_EQ(board.Name(), name);
  Blackboard unnamed(hub);
  EXPECT_EQ(unnamed.Name(), "");
  board.PublishMessage("behavior", Kind::State, Head(3));
  EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior")->ballfound(), 3);
  EXPECT_EQ(board.Name(), name);
}

TEST_F(Messaging, ThreadsThatUseAFreshBlackboardAtOnceShareWhatTheyMake) {
  // What a blackboard holds is made by its first use; threads that come at once must all end up
  // in the same contents (ThreadSanitizer checks the making).
  for (int round = 0; round < 20; ++round) {
    Blackboard board(hub);
    constexpr int kThreads = 4;
    std::atomic<int> ready{0};
    std::vector<std::thread> threads;
    for (int t = 0; t < kThreads; ++t) {
      threads.emplace_back([&, t] {
        ++ready;
        while (ready.load() < kThreads) {
        }
        switch (t) {
          case 0: board.Subscribe("behavior"); break;
          case 1: board.PublishMessage("motion", Kind::Signal, Head(1)); break;
          case 2: board.ScheduleWakeup(clock.Now()); break;
          default: {
            kse::messaging::Reader<HeadToBMessage> reader(board, "motion");
            (void)reader.ReadSignal();  // the publish's signal, or none yet
          }
        }
      });
    }
    for (auto& thread : threads) thread.join();
    EXPECT_TRUE(board.IsSubscribed("behavior"));
    EXPECT_EQ(hub.SubscriberCount("behavior"), 1U);
    EXPECT_LE(board.PendingSignals("motion", "HeadToBMessage"), 1U);
    EXPECT_TRUE(board.TakeDueWakeups(clock.Now()));
    hub.Publish("behavior", Kind::State, Head(round));
    board.ProcessMessages();
    EXPECT_EQ(board.ReadState<HeadToBMessage>("behavior")->ballfound(), round);
  }
}

TEST(Recycled, GivesAMessageBackOnlyOnceNobodyElseHoldsIt) {
  kse::messaging::Recycled<HeadToBMessage> messages(8);
  HeadToBMessage& first = messages.Next();
  first.set_ballfound(1);
  std::shared_ptr<const HeadToBMessage> kept = messages.Last();  // a reader keeps it
  HeadToBMessage& second = messages.Next();
  EXPECT_NE(&second, &first) << "a message someone holds is not written again";
  second.set_ballfound(2);
  kept.reset();
  HeadToBMessage& third = messages.Next();
  EXPECT_EQ(&third, &first) << "the oldest, let go of, is used again";
  EXPECT_EQ(third.ballfound(), 1) << "as it was";
  EXPECT_EQ(messages.Last().get(), &first);
  EXPECT_EQ(messages.Size(), 2U);
}

TEST(Recycled, LeavesTheOldestToItsHoldersAtTheLimit) {
  kse::messaging::Recycled<HeadToBMessage> messages(3);
  std::vector<std::shared_ptr<const HeadToBMessage>> held;
  for (int i = 0; i < 10; ++i) {
    messages.Next().set_ballfound(i);
    held.push_back(messages.Last());
  }
  EXPECT_EQ(messages.Size(), 3U) << "no more than the limit out at a time";
  for (int i = 0; i < 10; ++i) EXPECT_EQ(held[static_cast<std::size_t>(i)]->ballfound(), i) << "held messages unchanged";
  held.clear();
  // the three it kept are free again: used in turn, oldest first
  HeadToBMessage* seen[3];
  for (auto& message : seen) message = &messages.Next();
  EXPECT_EQ(seen[0]->ballfound(), 7);
  EXPECT_EQ(seen[1]->ballfound(), 8);
  EXPECT_EQ(seen[2]->ballfound(), 9);
  EXPECT_EQ(messages.Size(), 3U);
}

}  // namespace
}  // namespace kse_test
