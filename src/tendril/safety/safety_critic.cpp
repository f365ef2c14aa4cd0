#include "tendril/safety/safety_critic.hpp"

#include <algorithm>
#include <span>
#include <string>
#include <vector>

#include "tendril/core/error.hpp"

namespace tendril::safety {

namespace {

constexpr int64_t kSafetyCriticFormat = 1;

}  // namespace

void SafetyCritic::save(const std::filesystem::path& file) const {
  require(!kind().empty(), "this safety critic has no file form", file.string());
  ArchiveWriter writer("safety_critic");
  writer.put("format", kSafetyCriticFormat);
  writer.put("kind", kind());
  write(writer);
  writer.commit(file);
}

std::unique_ptr<SafetyCritic> load_safety_critic(const std::filesystem::path& file) {
  const ArchiveReader reader(file, "safety_critic");
  try {
    const int64_t format = reader.get_int("format");
    if (format != kSafetyCriticFormat) {
      throw Error("safety critic format " + std::to_string(format) +
                      " is not supported (this build reads " + std::to_string(kSafetyCriticFormat) +
                      ")",
                  reader.name());
    }
    const std::string kind = reader.get_string("kind");
    if (kind != "sac" && kind != "dqn") {
      throw Error("unknown safety critic kind '" + kind + "'", reader.name());
    }
    const Snapshot bytes = reader.get_bytes("policy");
    std::unique_ptr<rl::Policy> policy = rl::load_policy_bytes(
        std::string(reinterpret_cast<const char*>(bytes.data()), bytes.size()),
        reader.name() + " (policy)");
    if (kind == "dqn") {
      auto* q_policy = dynamic_cast<rl::QGreedyPolicy*>(policy.get());
      if (q_policy == nullptr) {
        throw Error("a dqn safety critic holds a '" + policy->kind() + "' policy", reader.name());
      }
      return std::make_unique<DqnSafetyCritic>(std::unique_ptr<const rl::QGreedyPolicy>(
          static_cast<rl::QGreedyPolicy*>(policy.release())));
    }
    if (!policy->action_space().is_box()) {
      throw Error("a sac safety critic needs a Box action space", reader.name());
    }
    const nn::DenseMlp shape = rl::read_mlp(reader, "critic");
    const std::vector<int64_t>& sizes = shape.sizes();
    const int64_t inputs = policy->observation_space().size() + policy->action_space().size();
    if (sizes.size() < 2 || sizes.front() != inputs || sizes.back() != 1) {
      throw Error("the critics' layer sizes do not fit the policy's spaces", reader.name());
    }
    const int64_t count = reader.get_int("critic_count");
    if (count < 1 || count > 16) {
      throw Error("implausible critic_count " + std::to_string(count), reader.name());
    }
    Rng unused(0);
    rl::QCritics critics(static_cast<int>(count), policy->observation_space().size(),
                         policy->action_space().size(),
                         std::vector<int64_t>(sizes.begin() + 1, sizes.end() - 1),
                         shape.hidden_activation(), 0.0, unused);
    critics.set_parameters(reader.get_floats("critic_parameters", critics.parameters().size()));
    return std::make_unique<SacSafetyCritic>(std::unique_ptr<const rl::Policy>(std::move(policy)),
                                             critics);
  } catch (const Error& e) {
    if (e.where() == reader.name()) throw;
    throw Error(e.what_wrong(), reader.name());
  }
}

SacSafetyCritic::SacSafetyCritic(const rl::Policy& actor, const rl::QCritics& critics)
    : actor_(actor), critics_(critics) {
  require(actor.action_space().is_box(), "a SAC safety critic needs a Box action space",
          "SacSafetyCritic");
}

SacSafetyCritic::SacSafetyCritic(const rl::Sac& agent)
    : SacSafetyCritic(agent.policy(), agent.critics()) {
  live_agent_ = &agent;
  synced_updates_ = agent.gradient_updates();
}

SacSafetyCritic::SacSafetyCritic(std::unique_ptr<const rl::Policy> actor,
                                 const rl::QCritics& critics)
    : owned_actor_(std::move(actor)), actor_(*owned_actor_), critics_(critics) {
  require(actor_.action_space().is_box(), "a SAC safety critic needs a Box action space",
          "SacSafetyCritic");
}

void SacSafetyCritic::write(ArchiveWriter& writer) const {
  const std::string policy = actor_.serialize();
  writer.put_bytes("policy", std::span<const std::byte>(
                                 reinterpret_cast<const std::byte*>(policy.data()), policy.size()));
  writer.put("critic_count", int64_t{critics_.count()});
  rl::write_mlp(writer, "critic", critics_.network(0));
  writer.put_floats("critic_parameters", critics_.parameters());
}

double SacSafetyCritic::value(const Observation& observation, const Action& action) const {
  if (live_agent_ != nullptr && live_agent_->gradient_updates() != synced_updates_) {
    critics_.set_parameters(live_agent_->critics().parameters());
    synced_updates_ = live_agent_->gradient_updates();
  }
  const auto obs_size = observation.size();
  // The critics see actions in [−1, 1].
  Eigen::MatrixXf unit_action = action;
  rl::unscale_from_bounds(actor_.action_space(), unit_action);
  inputs_.resize(obs_size + action.size(), 1);
  inputs_.col(0) << observation, unit_action.col(0);
  critics_.forward(inputs_, /*target=*/false);
  return static_cast<double>(critics_.values().col(0).minCoeff());
}

Action SacSafetyCritic::safe_action(const Observation& observation) const {
  return actor_.act(observation, /*deterministic=*/true, unused_rng_);
}

DqnSafetyCritic::DqnSafetyCritic(const rl::QGreedyPolicy& q_policy) : q_policy_(q_policy) {}

DqnSafetyCritic::DqnSafetyCritic(std::unique_ptr<const rl::QGreedyPolicy> q_policy)
    : owned_q_policy_(std::move(q_policy)), q_policy_(*owned_q_policy_) {}

void DqnSafetyCritic::write(ArchiveWriter& writer) const {
  const std::string policy = q_policy_.serialize();
  writer.put_bytes("policy", std::span<const std::byte>(
                                 reinterpret_cast<const std::byte*>(policy.data()), policy.size()));
}

double DqnSafetyCritic::value(const Observation& observation, const Action& action) const {
  const auto index = static_cast<Eigen::Index>(action[0]);
  const Eigen::MatrixXf& q = q_policy_.q_values(observation);
  require(index >= 0 && index < q.rows(), "action index out of range", "DqnSafetyCritic");
  return static_cast<double>(q(index, 0));
}

Action DqnSafetyCritic::safe_action(const Observation& observation) const {
  Eigen::Index best = 0;
  q_policy_.q_values(observation).col(0).maxCoeff(&best);
  return Action::Constant(1, static_cast<float>(best));
}

}  // namespace tendril::safety
