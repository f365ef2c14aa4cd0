"""Training throughput of seed 001's LSTM and Seq2Seq-with-attention dynamics models in PyTorch.

The baseline run by dynamics_training_bench in the same run: same architecture, batch, window and
thread count as tendril's models (tendril/dynamics/recurrent_network.cpp, seq2seq_network.cpp).
Prints one line: "windows_per_second <value>": the batch size over the median processor time
(of this thread) of one batch, which other programs on a busy machine disturb far less than wall
time or the mean.
"""
import argparse
import time

import torch
from torch import nn


class RecurrentModel(nn.Module):
    def __init__(self, features, hidden, layers, states, bound):
        super().__init__()
        self.lstm = nn.LSTM(features, hidden, layers, batch_first=True)
        self.head = nn.Linear(hidden, states)
        self.bound = bound

    def forward(self, windows):
        outputs, _ = self.lstm(windows)
        return torch.tanh(self.head(outputs[:, -1, :])) * self.bound


class Seq2SeqAttention(nn.Module):
    def __init__(self, features, hidden, layers, heads, states, bound):
        super().__init__()
        self.encoder = nn.LSTM(features, hidden, layers, batch_first=True)
        self.query = nn.Linear(features, hidden)
        self.attention = nn.MultiheadAttention(hidden, heads)
        self.back = nn.Linear(hidden, features)
        self.decoder = nn.LSTM(features, hidden, layers, batch_first=True)
        self.head = nn.Linear(hidden, states)
        self.bound = bound

    def forward(self, windows):
        encoded, state = self.encoder(windows)
        step = windows[:, -1:, :]
        query = self.query(step).transpose(0, 1)
        memory = encoded.transpose(0, 1)
        attended, _ = self.attention(query, memory, memory, need_weights=False)
        step = self.back(attended.transpose(0, 1))
        decoded, _ = self.decoder(step, state)
        return torch.tanh(self.head(decoded[:, 0, :])) * self.bound


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--architecture", choices=["lstm", "seq2seq_attention"], required=True)
    parser.add_argument("--hidden", type=int, default=64)
    parser.add_argument("--layers", type=int, default=2)
    parser.add_argument("--heads", type=int, default=4)
    parser.add_argument("--window", type=int, default=100)
    parser.add_argument("--batch", type=int, default=256)
    parser.add_argument("--batches", type=int, default=10)
    parser.add_argument("--threads", type=int, default=1)
    args = parser.parse_args()

    torch.set_num_threads(args.threads)
    torch.manual_seed(0)
    states, inputs = 4, 2
    features = states + inputs
    if args.architecture == "lstm":
        model = RecurrentModel(features, args.hidden, args.layers, states, 100.0)
    else:
        model = Seq2SeqAttention(features, args.hidden, args.layers, args.heads, states, 100.0)
    optimizer = torch.optim.Adam(model.parameters(), lr=1e-3)
    windows = torch.randn(args.batch, args.window, features)
    targets = torch.randn(args.batch, states)

    def step():
        optimizer.zero_grad()
        loss = nn.functional.mse_loss(model(windows), targets)
        loss.backward()
        nn.utils.clip_grad_value_(model.parameters(), 1.0)
        optimizer.step()
        return loss.item()

    step()  # warm-up
    times = []
    for _ in range(args.batches):
        start = time.thread_time()
        step()
        times.append(time.thread_time() - start)
    times.sort()
    print(f"windows_per_second {args.batch / times[len(times) // 2]:.6g}")


if __name__ == "__main__":
    main()
