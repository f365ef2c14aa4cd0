// Loading models (and refusing bad ones with tendril::Error), MuJoCo's fatal errors, and exact
// snapshots of the simulation state.
#include "tendril/physics/rigid/mujoco_sim.hpp"

#include <gtest/gtest.h>
#include <mujoco/mujoco.h>

#include <fstream>
#include <vector>

#include "support/error_message.hpp"
#include "support/scratch_directory.hpp"
#include "tendril/core/error.hpp"

namespace tendril::physics {
namespace {

using testing::error_message;

// A box falling onto a plane and sliding: contacts make the solver's warm start matter.
constexpr const char* kFallingBox = R"(
<mujoco>
  <option timestep="0.002"/>
  <worldbody>
    <geom name="floor" type="plane" size="2 2 0.1"/>
    <body name="box" pos="0 0 0.3" euler="0.3 0.2 0.1">
      <freejoint/>
      <geom type="box" size="0.05 0.08 0.03" mass="1"/>
    </body>
  </worldbody>
</mujoco>)";

std::vector<double> qpos_of(const MujocoSim& sim) {
  const mjModel* m = sim.model();
  return std::vector<double>(sim.data()->qpos, sim.data()->qpos + m->nq);
}

void step(MujocoSim& sim, int steps) {
  for (int i = 0; i < steps; ++i) mj_step(sim.model(), sim.data());
}

TEST(MujocoSim, MalformedModelTextRaisesErrorWithMuJoCosMessage) {
  const std::string message =
      error_message([] { MujocoSim::from_xml("<mujoco><worldbody><body>", "broken scene"); });
  EXPECT_NE(message.find("broken scene"), std::string::npos) << message;
  EXPECT_NE(message.find("MuJoCo rejected the model"), std::string::npos) << message;

  const std::string unknown = error_message([] {
    MujocoSim::from_xml("<mujoco><worldbody><geom type='teapot' size='1'/></worldbody></mujoco>",
                        "teapot");
  });
  EXPECT_NE(unknown.find("teapot"), std::string::npos) << unknown;
}

class MujocoSimFiles : public testing::ScratchDirectoryTest {
 protected:
  MujocoSimFiles() : ScratchDirectoryTest("mujoco_sim") {}
};

TEST_F(MujocoSimFiles, MissingOrBadModelFileRaisesErrorNamingTheFile) {
  const auto missing = directory_ / "absent.xml";
  EXPECT_NE(error_message([&] { MujocoSim::from_file(missing); }).find("absent.xml"),
            std::string::npos);

  const auto bad = directory_ / "bad.xml";
  std::ofstream(bad) << "<mujoco><worldbody><geom type='box' size='-1'/></worldbody></mujoco>";
  const std::string message = error_message([&] { MujocoSim::from_file(bad); });
  EXPECT_NE(message.find("bad.xml"), std::string::npos) << message;
  EXPECT_NE(message.find("MuJoCo rejected the model"), std::string::npos) << message;

  const auto good = directory_ / "good.xml";
  std::ofstream(good) << kFallingBox;
  EXPECT_EQ(MujocoSim::from_file(good).model()->nq, 7);
}

TEST(MujocoSim, UnknownElementNamesAreErrors) {
  const MujocoSim sim = MujocoSim::from_xml(kFallingBox, "falling box");
  EXPECT_EQ(sim.id_of(mjOBJ_BODY, "box"), 1);
  const std::string message = error_message([&] { sim.id_of(mjOBJ_SITE, "tool"); });
  EXPECT_NE(message.find("'tool'"), std::string::npos) << message;
}

TEST(MujocoSim, MuJoCosFatalErrorsBecomeTendrilErrors) {
  MujocoSim::install_handlers();
  EXPECT_THROW(mju_error("out of memory in a test"), Error);
  EXPECT_NE(error_message([] { mju_error_i("stack overflow %d", 3); }).find("stack overflow 3"),
            std::string::npos);
}

TEST(MujocoSim, SteppingOnAfterLoadStateRepeatsTheOriginalExactly) {
  MujocoSim original = MujocoSim::from_xml(kFallingBox, "falling box");
  step(original, 150);  // in contact with the floor by now
  ASSERT_GT(original.data()->ncon, 0);
  Snapshot bytes;
  SnapshotWriter out(bytes);
  original.save_state(out);

  MujocoSim copy = MujocoSim::from_xml(kFallingBox, "falling box");
  step(copy, 37);  // somewhere else entirely
  SnapshotReader in(bytes);
  copy.load_state(in);
  EXPECT_TRUE(in.at_end());

  for (int block = 0; block < 5; ++block) {
    step(original, 40);
    step(copy, 40);
    ASSERT_EQ(qpos_of(copy), qpos_of(original)) << "block " << block;
  }
  EXPECT_EQ(copy.data()->time, original.data()->time);
}

TEST(MujocoSim, CopiesShareTheModelButNotTheState) {
  MujocoSim original = MujocoSim::from_xml(kFallingBox, "falling box");
  MujocoSim copy(original);
  EXPECT_EQ(copy.model(), original.model());
  step(copy, 100);
  EXPECT_NE(qpos_of(copy), qpos_of(original));
  original = copy;
  EXPECT_EQ(qpos_of(copy), qpos_of(original));
}

TEST(MujocoSim, ASnapshotOfAnotherModelIsRefusedAndChangesNothing) {
  MujocoSim box = MujocoSim::from_xml(kFallingBox, "falling box");
  MujocoSim pendulum = MujocoSim::from_xml(
      "<mujoco><worldbody><body><joint type='hinge'/><geom type='capsule' fromto='0 0 0 0 0 -1' "
      "size='0.05'/></body></worldbody></mujoco>",
      "pendulum");
  Snapshot bytes;
  SnapshotWriter out(bytes);
  pendulum.save_state(out);
  step(box, 10);
  const std::vector<double> before = qpos_of(box);
  SnapshotReader in(bytes);
  EXPECT_NE(error_message([&] { box.load_state(in); }), "no error");
  EXPECT_EQ(qpos_of(box), before);
}

}  // namespace
}  // namespace tendril::physics
