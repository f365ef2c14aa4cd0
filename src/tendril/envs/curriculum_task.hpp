#pragma once

namespace tendril::envs {

// A task with levels of difficulty, 0 (easiest) to curriculum_levels() − 1 (the full task),
// that a Curriculum wrapper moves it through. What a level means is the task's own (ranges of
// target parameters, say); the rule for moving on is the wrapper's. Without a curriculum a task
// runs at its last level.
class CurriculumTask {
 public:
  virtual ~CurriculumTask() = default;

  virtual int curriculum_levels() const = 0;  // at least 1
  virtual int curriculum_level() const = 0;
  // Takes effect at the next reset. Raises tendril::Error outside [0, curriculum_levels()).
  virtual void set_curriculum_level(int level) = 0;
};

}  // namespace tendril::envs
