"""SAC's gradient step with seed 001's LK Encoder policy head in PyTorch (the author's code is
CleanRL's SAC on PyTorch): the baseline learned_reach_bench runs in the same run.

Same networks and sizes as tendril's run of configs/sma_limb/learned_reach_sac_lk_encoder.yaml: a
2-layer LSTM encoder (hidden 64) over a window of 100 rows of 6 values, LayerNorm without gain and
bias, actor and twin critics with one hidden layer of 256 reading [features, 14 direct values]
(+ 2 actions), batch 256, Adam, α learned, Polyak targets (the head's too when it trains). With
--frozen the head's weights do not train; as in the author's code it still runs on every batch
(observations and next observations, without gradients). Prints "gradient_steps_per_second
<value>": one over the median processor time of this thread per gradient step.
"""
import argparse
import copy
import math
import time

import torch
from torch import nn
import torch.nn.functional as F


class Encoder(nn.Module):
    def __init__(self, hidden, layers):
        super().__init__()
        self.lstm = nn.LSTM(6, hidden, layers, batch_first=True)
        self.hidden = hidden

    def forward(self, history):
        outputs, _ = self.lstm(history)
        return F.layer_norm(outputs[:, -1, :], (self.hidden,))


def mlp(inputs, hidden, outputs):
    return nn.Sequential(nn.Linear(inputs, hidden), nn.ReLU(), nn.Linear(hidden, outputs))


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--hidden", type=int, default=64)
    parser.add_argument("--layers", type=int, default=2)
    parser.add_argument("--window", type=int, default=100)
    parser.add_argument("--batch", type=int, default=256)
    parser.add_argument("--net", type=int, default=256)
    parser.add_argument("--steps", type=int, default=20)
    parser.add_argument("--frozen", action="store_true")
    parser.add_argument("--threads", type=int, default=1)
    args = parser.parse_args()
    torch.set_num_threads(args.threads)
    torch.manual_seed(0)

    direct, actions = 14, 2
    encoder = Encoder(args.hidden, args.layers)
    target_encoder = copy.deepcopy(encoder)
    features = args.hidden + direct
    actor = mlp(features, args.net, 2 * actions)
    critics = [mlp(features + actions, args.net, 1) for _ in range(2)]
    targets = [copy.deepcopy(c) for c in critics]
    log_alpha = torch.zeros(1, requires_grad=True)
    q_params = [p for c in critics for p in c.parameters()]
    q_optimizer = torch.optim.Adam(q_params, lr=5e-4)
    actor_optimizer = torch.optim.Adam(actor.parameters(), lr=5e-4)
    alpha_optimizer = torch.optim.Adam([log_alpha], lr=5e-4)
    head_optimizer = None if args.frozen else torch.optim.Adam(encoder.parameters(), lr=5e-4)

    b, w = args.batch, args.window
    history = torch.randn(b, w, 6)
    next_history = torch.randn(b, w, 6)
    rest = torch.randn(b, direct)
    next_rest = torch.randn(b, direct)
    taken = torch.rand(b, actions) * 2 - 1
    rewards = torch.randn(b, 1)
    dones = (torch.rand(b, 1) < 0.05).float()

    def sample(inputs):
        out = actor(inputs)
        mean, log_std = out[:, :actions], torch.clamp(out[:, actions:], -5, 2)
        std = log_std.exp()
        u = mean + std * torch.randn_like(mean)
        a = torch.tanh(u)
        log_prob = (-(u - mean) ** 2 / (2 * std ** 2) - log_std - 0.5 * math.log(2 * math.pi)).sum(
            1, keepdim=True) - torch.log(1 - a ** 2 + 1e-6).sum(1, keepdim=True)
        return a, log_prob

    def encode(net, h, r, grad):
        with torch.set_grad_enabled(grad):
            return torch.cat([net(h), r], 1)

    def step():
        trains = head_optimizer is not None
        s = encode(encoder, history, rest, trains)
        with torch.no_grad():
            s_next = encode(encoder, next_history, next_rest, False)
            s_target = encode(target_encoder, next_history, next_rest, False) if trains else s_next
            a_next, logp_next = sample(s_next)
            q_next = torch.min(*[t(torch.cat([s_target, a_next], 1)) for t in targets])
            y = rewards + 0.99 * (1 - dones) * (q_next - log_alpha.exp() * logp_next)
        q_loss = sum(F.mse_loss(c(torch.cat([s, taken], 1)), y) for c in critics)
        q_optimizer.zero_grad()
        if trains:
            head_optimizer.zero_grad()
        q_loss.backward(retain_graph=trains)
        nn.utils.clip_grad_norm_(q_params, 1.0)
        q_optimizer.step()
        a, logp = sample(s if trains else s.detach())
        s_in = s if trains else s.detach()
        q_pi = torch.min(*[c(torch.cat([s_in, a], 1)) for c in critics])
        actor_loss = (log_alpha.exp().detach() * logp - q_pi).mean()
        actor_optimizer.zero_grad()
        actor_loss.backward()
        nn.utils.clip_grad_norm_(actor.parameters(), 1.0)
        actor_optimizer.step()
        alpha_loss = (-log_alpha.exp() * (logp.detach() - 2)).mean()
        alpha_optimizer.zero_grad()
        alpha_loss.backward()
        alpha_optimizer.step()
        if trains:
            nn.utils.clip_grad_norm_(encoder.parameters(), 1.0)
            head_optimizer.step()
        with torch.no_grad():
            pairs = list(zip(critics, targets))
            if trains:
                pairs.append((encoder, target_encoder))
            for online, target in pairs:
                for p, t in zip(online.parameters(), target.parameters()):
                    t.mul_(0.995).add_(p, alpha=0.005)

    step()  # warm-up
    times = []
    for _ in range(args.steps):
        start = time.thread_time()
        step()
        times.append(time.thread_time() - start)
    times.sort()
    print("gradient_steps_per_second", 1.0 / times[len(times) // 2])


if __name__ == "__main__":
    main()
