#include "tendril/adapt/student_policy.hpp"

#include <gtest/gtest.h>

#include "scripted_reaching_robot.hpp"
#include "tendril/core/error.hpp"

namespace tendril::adapt {
namespace {

using testing::LinearArm;

// Transitions of the static linear arm x_{t+1} = rest + B a_t from random commands: the
// student, asked for x^d, answers the command that reaches it, B⁻¹(x^d − rest), eq. (3).
TEST(StudentPolicy, LearnsTheInverseOfALinearArmFromReformedTransitions) {
  const LinearArm arm;
  StudentPolicy student(3, 3, GpOptions{});
  Rng rng(1);
  Eigen::Vector3d state = arm.at(Eigen::Vector3d::Constant(-1.0));
  for (int t = 0; t < 150; ++t) {
    Eigen::Vector3d command;
    for (int i = 0; i < 3; ++i) command[i] = rng.uniform(-1.0, 1.0);
    const Eigen::Vector3d next = arm.at(command);
    student.add(state, next, command);
    state = next;
  }
  EXPECT_EQ(student.size(), 150);
  student.fit_hyperparameters(rng);
  for (const Eigen::Vector3d wanted :
       {Eigen::Vector3d(0.3, -0.2, 0.1), Eigen::Vector3d(-0.5, 0.4, -0.6)}) {
    const Eigen::VectorXd answer = student.act(state, arm.at(wanted));
    EXPECT_LT((answer - wanted).norm(), 0.05) << answer.transpose();
  }
  // Answers are clipped to the command range.
  const Eigen::VectorXd beyond = student.act(state, arm.at(Eigen::Vector3d(3.0, 0.0, 0.0)));
  EXPECT_LE(beyond.maxCoeff(), 1.0);
}

TEST(StudentPolicy, WithoutDataOrWithWrongSizesItRefuses) {
  StudentPolicy student(3, 3, GpOptions{});
  EXPECT_THROW(student.act(Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()), Error);
  EXPECT_THROW(
      student.add(Eigen::Vector2d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()),
      Error);
  student.add(Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), Eigen::Vector3d::Zero());
  EXPECT_THROW(
      student.add(Eigen::Vector3d::Zero(), Eigen::Vector3d::Constant(NAN), Eigen::Vector3d::Zero()),
      Error);
  EXPECT_THROW(student.set_command_bounds(1.0, -1.0), Error);
}

}  // namespace
}  // namespace tendril::adapt
