"""Trained policies for other runtimes: a dependency-free C header (for a microcontroller) and an
ONNX model. Both compute the policy's deterministic action from a raw observation: the
observation normalization, the layers, then the action's squash and scaling (or argmax).

    python3 -m tendril.export RUN_OR_POLICY --c policy.h [--name NAME] [--best]
    python3 -m tendril.export RUN_OR_POLICY --onnx policy.onnx [--best]
"""
import argparse
import os
import sys

import numpy as np

from . import _tendril

ONNX_OPSET = 13


def network(policy, best=False):
    """The policy's deterministic action as layers: {"kind", "observation_size", "mean",
    "scale", "clip", "layers": [{"weight", "bias", "activation"}], "output", "low", "high",
    "action_size", "action_choices"} (rl::PolicyNetwork)."""
    return _tendril.policy_network(os.fspath(policy), bool(best))


def export_c_header(policy, out, name="policy", best=False):
    """Writes the policy (a run directory or a .policy file) as the C header `out`: float
    weights and `<name>_act(observation, action)`. Never replaces an existing file."""
    _tendril.export_c_header(os.fspath(policy), os.fspath(out), name, bool(best))


def onnx_model(policy, best=False, opset=ONNX_OPSET):
    """The policy as an onnx.ModelProto with input "observation" (batch x observation_size,
    float32) and output "action" (batch x action_size float32, or batch int64 indices)."""
    import onnx
    from onnx import TensorProto, helper, numpy_helper

    net = network(policy, best)
    nodes, initializers = [], []

    def constant(name, values, dtype=np.float32):
        initializers.append(numpy_helper.from_array(np.asarray(values, dtype=dtype), name))
        return name

    x = "observation"
    if net["mean"] is not None:
        nodes.append(helper.make_node("Sub", [x, constant("mean", net["mean"])], ["centred"]))
        nodes.append(helper.make_node("Mul", ["centred", constant("scale", net["scale"])],
                                      ["scaled"]))
        nodes.append(helper.make_node("Clip", ["scaled", constant("clip_low", -net["clip"]),
                                               constant("clip_high", net["clip"])],
                                      ["normalized"]))
        x = "normalized"
    activations = {"tanh": "Tanh", "relu": "Relu", "softsign": "Softsign"}
    for k, layer in enumerate(net["layers"]):
        out = f"layer{k}"
        nodes.append(helper.make_node("Gemm", [x, constant(f"weight{k}", layer["weight"]),
                                               constant(f"bias{k}", layer["bias"])], [out],
                                      transB=1))
        if layer["activation"] != "none":
            nodes.append(helper.make_node(activations[layer["activation"]], [out],
                                          [f"{out}_{layer['activation']}"]))
            out = f"{out}_{layer['activation']}"
        x = out

    output = net["output"]
    if output == "argmax":
        nodes.append(helper.make_node("ArgMax", [x], ["action"], axis=1, keepdims=0,
                                      select_last_index=0))
        action = helper.make_tensor_value_info("action", TensorProto.INT64, ["batch"])
    else:
        low, high = constant("low", net["low"]), constant("high", net["high"])
        if output == "clip":
            nodes.append(helper.make_node("Max", [x, low], ["above_low"]))
            nodes.append(helper.make_node("Min", ["above_low", high], ["action"]))
        else:
            if output == "clamp_tanh_scale":  # SAC with gSDE: tanh of the mean clipped to ±2
                nodes.append(helper.make_node("Clip", [x, constant("two_low", -2.0),
                                                       constant("two_high", 2.0)], ["clamped"]))
                nodes.append(helper.make_node("Tanh", ["clamped"], ["squashed"]))
                x = "squashed"
            nodes.append(helper.make_node("Clip", [x, constant("one_low", -1.0),
                                                   constant("one_high", 1.0)], ["unit"]))
            nodes.append(helper.make_node("Add", ["unit", constant("one", 1.0)], ["shifted"]))
            half_range = 0.5 * (np.asarray(net["high"]) - np.asarray(net["low"]))
            nodes.append(helper.make_node("Mul", ["shifted", constant("half_range", half_range)],
                                          ["stretched"]))
            nodes.append(helper.make_node("Add", ["stretched", low], ["action"]))
        action = helper.make_tensor_value_info("action", TensorProto.FLOAT,
                                               ["batch", net["action_size"]])
    graph = helper.make_graph(
        nodes, f"tendril_{net['kind']}_policy",
        [helper.make_tensor_value_info("observation", TensorProto.FLOAT,
                                       ["batch", net["observation_size"]])],
        [action], initializers)
    model = helper.make_model(graph, producer_name="tendril",
                              opset_imports=[helper.make_opsetid("", opset)])
    model.doc_string = (f"tendril {net['kind']} policy: deterministic action from a raw "
                        f"observation ({output} output)")
    onnx.checker.check_model(model)
    return model


def export_onnx(policy, out, best=False, opset=ONNX_OPSET):
    """Writes the policy as the ONNX file `out` (checked with onnx.checker). Never replaces an
    existing file."""
    import onnx

    out = os.fspath(out)
    if os.path.exists(out):
        raise _tendril.Error(f"{out}: exists already; not overwriting it")
    model = onnx_model(policy, best, opset)
    partial = f"{out}.partial-{os.getpid()}"
    onnx.save(model, partial)
    try:
        os.link(partial, out)  # fails rather than replace a file that appeared meanwhile
    finally:
        os.unlink(partial)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="tendril export", description=__doc__.split("\n\n")[0])
    parser.add_argument("policy", help="a run directory (its model.policy) or a .policy file")
    parser.add_argument("--c", metavar="FILE.h", help="write a C header")
    parser.add_argument("--name", default="policy", help="the C header's identifier prefix")
    parser.add_argument("--onnx", metavar="FILE.onnx", help="write an ONNX model")
    parser.add_argument("--best", action="store_true", help="the run's best_model.policy")
    args = parser.parse_args(argv)
    if not args.c and not args.onnx:
        parser.error("nothing to write: give --c FILE.h and/or --onnx FILE.onnx")
    try:
        if args.c:
            export_c_header(args.policy, args.c, args.name, args.best)
            print(f"wrote {args.c}")
        if args.onnx:
            export_onnx(args.policy, args.onnx, args.best)
            print(f"wrote {args.onnx}")
    except (_tendril.Error, ImportError) as error:
        print(f"tendril export: error: {error}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
