#pragma once

#include <functional>

namespace tendril {

// The dynamics layer (learned models, the only layer on LibTorch) may come into a program only
// when something first needs it: the command line keeps it in a plugin, so that commands without
// learned models never load LibTorch (docs/architecture.md). Such a program sets how the layer
// is loaded; the lookups of what the layer installs below it (the model loader of learned-model
// environments, the learned-model policy heads) ask for it when they find nothing installed.
// Programs that link the layer install it at start-up and need none of this.
void set_dynamics_layer_loader(std::function<void()> load);

// Loads the layer with the loader set, once per program (a load that raised is tried again at
// the next call, and raises again); false when no loader is set. Safe from several threads: the
// first caller loads, the others wait for it.
bool load_dynamics_layer();

}  // namespace tendril
