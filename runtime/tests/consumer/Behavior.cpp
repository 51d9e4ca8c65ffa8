// Self-registering activity and statechart, as generated code registers them.
#include <memory>

#include "consumer/Extra.pb.h"
#include "statechart_engine/statechart_engine.h"

namespace {

class PlanKick : public statechart_engine::IActivity {
 public:
  int Execute() override {
    KickPlan plan;
    plan.mutable_ball()->set_relativex(0.12F);
    _blk->Publish("behavior", kse::messaging::Kind::State, plan);
    return 0;
  }
  std::string GetName() override { return "PlanKick"; }
};
statechart_engine::ActivityRegistrar<PlanKick>::Type temp("PlanKick");

class Planned : public statechart_engine::ICondition {
 public:
  void UserInit() override { _blk->Subscribe("behavior"); }
  bool Eval() override {
    auto plan = _blk->ReadState<KickPlan>("behavior");
    auto gsm = _blk->ReadState<GameStateMessage>("worldstate");
    (void)gsm;
    return plan != nullptr && plan->has_ball();
  }
};

class Consumer : public statechart_engine::IStatechart {
 public:
  Consumer(kse::messaging::MessageHub& hub, const statechart_engine::Options& options)
      : chart_(std::make_unique<statechart_engine::Statechart>("Consumer", hub, options)) {
    using namespace statechart_engine;
    auto* s = chart_->Add<StartState>("Node_0_1", chart_.get());
    auto* plan = chart_->Add<BasicState>("PlanKick", chart_.get(), ActivityFactory::Instance().Create("PlanKick"));
    auto* end = chart_->Add<EndState>("Node_0_3", chart_.get());
    chart_->AddTransition(s, plan, nullptr, std::make_unique<TimeoutAction>("behavior", 10));
    chart_->AddTransition(plan, end, std::make_unique<Planned>());
  }
  void Start() override { chart_->Start(); }
  void Stop() override { chart_->Stop(); }
  statechart_engine::Statechart& Chart() override { return *chart_; }

 private:
  std::unique_ptr<statechart_engine::Statechart> chart_;
};
statechart_engine::StatechartRegistrar<Consumer>::Type chartRegistrar("Consumer");

}  // namespace
