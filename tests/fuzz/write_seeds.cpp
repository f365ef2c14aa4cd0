// Writes the binary seeds of the fuzz targets into <directory>/<target>/: a PPO checkpoint and
// policy (archive_fuzz), a short recorded episode (episode_fuzz), an event file (event_file_fuzz,
// with its mode byte), a replay buffer (replay_buffer_fuzz), a progress.csv and a pneumatic-arm
// recording (table_fuzz) and a learned dynamics model file (model_file_fuzz), each written by the
// code that writes them for users.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "tendril/core/episode_writer.hpp"
#include "tendril/core/scalar_log.hpp"
#include "tendril/dynamics/model_file_format.hpp"
#include "tendril/envs/pneumatic/pneumatic_dataset.hpp"
#include "tendril/rl/ppo/ppo.hpp"
#include "tendril/rl/replay_buffer.hpp"
#include "tendril/rl/vec_env_factory.hpp"

namespace fs = std::filesystem;
using namespace tendril;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: %s <corpus directory>\n", argv[0]);
    return 2;
  }
  const fs::path root = argv[1];
  for (const char* target : {"archive_fuzz", "episode_fuzz", "event_file_fuzz",
                             "replay_buffer_fuzz", "table_fuzz", "model_file_fuzz"}) {
    fs::create_directories(root / target);
  }

  rl::VecEnvOptions options;
  options.id = "Pendulum-v1";
  auto env = rl::make_vec_env(options);
  rl::Ppo ppo(*env,
              rl::PpoConfig::from_config(Config::parse("n_steps: 16\nbatch_size: 8\n"
                                                       "policy: {net_arch: [4]}\n")),
              0);
  ppo.learn(16);
  ppo.save(root / "archive_fuzz" / "step_16.ckpt");
  ppo.save_policy(root / "archive_fuzz" / "model.policy");

  const fs::path episode = root / "episode_fuzz" / "episode.tep";
  fs::remove(episode);
  {
    EpisodeWriter writer(episode, {{"env", "seed"}}, 1);
    for (int k = 0; k <= 3; ++k) {
      EpisodeFrame frame;
      frame.step = k;
      frame.scene.time = 0.05 * k;
      frame.scene.values = {{"distance", 0.1 * k}};
      if (k > 0) {
        frame.reward = -0.1 * k;
        frame.action = Action::Constant(1, 0.5f);
        frame.info = {{"distance", 0.1 * k}};
      }
      frame.truncated = k == 3;
      writer.write(frame);
    }
    writer.finish();
  }

  const fs::path logs = root / "logs";
  fs::remove_all(logs);
  {
    ScalarLog log(logs);
    for (int step = 1; step <= 3; ++step) {
      log.record("rollout/ep_rew_mean", -100.0 * step);
      log.record("train/value_loss", 0.5 / step);
      log.dump(step * 100);
    }
    fs::copy_file(log.csv_path(), root / "table_fuzz" / "progress.csv",
                  fs::copy_options::overwrite_existing);
    for (const auto& entry : fs::directory_iterator(logs)) {
      if (entry.path().filename().string().rfind("events.", 0) != 0) continue;
      std::ifstream in(entry.path(), std::ios::binary);
      const std::string bytes((std::istreambuf_iterator<char>(in)), {});
      std::ofstream(root / "event_file_fuzz" / "events", std::ios::binary) << '\0' << bytes;
    }
  }
  fs::remove_all(logs);

  rl::ReplayBuffer buffer(64, 3, 1);
  for (int i = 0; i < 5; ++i) {
    const Eigen::VectorXf observation = Eigen::VectorXf::Constant(3, 0.1f * i);
    buffer.add(observation, Eigen::VectorXf::Constant(1, 0.2f), 1.0f, observation, i == 4);
  }
  buffer.save(root / "replay_buffer_fuzz" / "buffer.bin");

  envs::pneumatic::PneumaticDataset recording;
  recording.metadata = {{"command", "collect-pneumatic"}, {"seed", "0"}};
  recording.time_s = Eigen::Vector3d(0.0, 0.1, 0.2);
  recording.commands_bar.setConstant(3, 9, 0.5);
  recording.pressures_bar.setConstant(3, 9, 0.4);
  recording.tips_mm.setConstant(3, 9, -120.0);
  const fs::path recording_file = root / "table_fuzz" / "pneumatic.csv";
  fs::remove(recording_file);
  envs::pneumatic::write_pneumatic_dataset(recording_file, recording);

  // A one-layer LSTM of seed 001's layout (4 states, 2 throttles, hidden size 4) with a linear
  // head: PyTorch's parameter shapes, 212 values as ArchitectureSpec::parameter_count says.
  dynamics::ModelFileContents model;
  dynamics::ArchitectureSpec& a = model.description.architecture;
  a.kind = dynamics::Architecture::kLstm;
  a.hidden_size = 4;
  a.layers = 1;
  a.window = 3;
  model.description.normalizer = dynamics::Normalizer::identity(6);
  model.description.state_names = {"theta_x", "theta_y", "omega_x", "omega_y"};
  model.description.input_names = {"u_x", "u_y"};
  model.description.sample_period = 0.075;
  const std::vector<std::pair<std::string, std::vector<int64_t>>> table = {
      {"lstm.weight_ih_l0", {16, 6}}, {"lstm.weight_hh_l0", {16, 4}}, {"lstm.bias_ih_l0", {16}},
      {"lstm.bias_hh_l0", {16}},      {"head.weight", {4, 4}},        {"head.bias", {4}}};
  for (const auto& [name, shape] : table) {
    int64_t count = 1;
    for (const int64_t size : shape) count *= size;
    std::vector<float> values(static_cast<std::size_t>(count));
    for (std::size_t i = 0; i < values.size(); ++i) values[i] = 0.01f * static_cast<float>(i);
    model.parameters.push_back({name, shape, values});
  }
  std::ofstream(root / "model_file_fuzz" / "model.tdm", std::ios::binary)
      << dynamics::encode_model_file(model);
  return 0;
}
