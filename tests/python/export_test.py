"""Policy export from Python: the ONNX model passes onnx.checker and, evaluated, gives tendril's
own deterministic actions for every kind of policy; the C header compiles; files are never
replaced."""
import shutil
import subprocess

import numpy as np
import pytest

from conftest import reference

import tendril
from tendril import export

import onnx  # scripts/setup installs python3-onnx; without it these tests fail
from onnx import numpy_helper

KINDS = ["ppo_gaussian", "trpo_softsign", "ppo_linear", "ppo_categorical", "sac", "sac_gsde",
         "td3", "dqn", "dqn_bounded"]


@pytest.fixture(scope="module")
def policies(tmp_path_factory):
    folder = tmp_path_factory.mktemp("policies")
    reference("sample-policies", folder)
    return folder


def evaluate(model, observations):
    """The model's output for `observations`: onnx's reference evaluator where this onnx has one
    (1.13 and later), else a direct NumPy reading of the graph's nodes (the operators the
    exporter uses, with ONNX's semantics)."""
    try:
        from onnx.reference import ReferenceEvaluator
    except ImportError:
        ReferenceEvaluator = None
    if ReferenceEvaluator is not None:
        return ReferenceEvaluator(model).run(None, {"observation": observations})[0]
    values = {t.name: numpy_helper.to_array(t) for t in model.graph.initializer}
    values["observation"] = observations
    for node in model.graph.node:
        inputs = [values[name] for name in node.input]
        attributes = {a.name: onnx.helper.get_attribute_value(a) for a in node.attribute}
        op = node.op_type
        if op == "Gemm":
            a, b, c = inputs
            assert attributes.get("transB") == 1 and not attributes.get("transA")
            out = a @ b.T + c
        elif op in ("Add", "Sub", "Mul", "Max", "Min"):
            out = {"Add": np.add, "Sub": np.subtract, "Mul": np.multiply, "Max": np.maximum,
                   "Min": np.minimum}[op](*inputs)
        elif op == "Clip":
            out = np.clip(inputs[0], inputs[1], inputs[2])
        elif op == "Tanh":
            out = np.tanh(inputs[0])
        elif op == "Relu":
            out = np.maximum(inputs[0], 0)
        elif op == "Softsign":
            out = inputs[0] / (1 + np.abs(inputs[0]))
        elif op == "ArgMax":
            assert attributes["axis"] == 1 and attributes["keepdims"] == 0
            out = np.argmax(inputs[0], axis=1).astype(np.int64)  # the first of equal maxima
        else:
            raise AssertionError(f"operator {op} is not read by this test")
        values[node.output[0]] = out.astype(inputs[0].dtype if op != "ArgMax" else np.int64)
    return values[model.graph.output[0].name]


@pytest.mark.parametrize("kind", KINDS)
def test_onnx_model_acts_as_tendril(policies, kind, tmp_path):
    file = policies / f"{kind}.policy"
    out = tmp_path / f"{kind}.onnx"
    tendril.export_onnx(file, out)
    model = onnx.load(out)
    onnx.checker.check_model(model, full_check=True)
    policy = tendril.load(file)
    observations = (4.0 * np.random.default_rng(3).standard_normal(
        (500, policy.observation_space.shape[0]))).astype(np.float32)
    ours = evaluate(model, observations)
    theirs = policy.act(observations, deterministic=True)
    if policy.kind in ("q_greedy",) or ours.dtype == np.int64:
        assert ours.shape == (500,)
        np.testing.assert_array_equal(ours, theirs)
    else:
        assert ours.shape == theirs.shape == (500, 3)
        span = policy.action_space.high - policy.action_space.low
        # Float rounding only (summation order, tanh): within 2e-5 of each action's range.
        assert np.all(np.abs(ours - theirs) <= 2e-5 * span), np.abs(ours - theirs).max()


def test_exports_never_replace_a_file(policies, tmp_path):
    kept = tmp_path / "kept.onnx"
    kept.write_text("kept")
    with pytest.raises(tendril.Error, match="exists already"):
        tendril.export_onnx(policies / "sac.policy", kept)
    kept_header = tmp_path / "kept.h"
    kept_header.write_text("kept")
    with pytest.raises(tendril.Error, match="exists"):
        tendril.export_c_header(policies / "sac.policy", kept_header)
    assert kept.read_text() == "kept" and kept_header.read_text() == "kept"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["kept.h", "kept.onnx"]


def test_c_header_from_python_compiles(policies, tmp_path):
    compiler = shutil.which("cc") or shutil.which("gcc")
    assert compiler, "no C compiler"
    header = tmp_path / "td3_policy.h"
    tendril.export_c_header(policies / "td3.policy", header, name="td3_policy")
    done = subprocess.run([compiler, "-std=c89", "-pedantic", "-Wall", "-Werror",
                           "-fsyntax-only", "-x", "c", str(header)], capture_output=True,
                          text=True)
    assert done.returncode == 0, done.stderr
    assert "void td3_policy_act(const float *observation, float *action)" in header.read_text()


def test_command_line_writes_both(policies, tmp_path):
    code = export.main([str(policies / "dqn.policy"), "--c", str(tmp_path / "dqn.h"),
                        "--name", "dqn", "--onnx", str(tmp_path / "dqn.onnx")])
    assert code == 0
    assert (tmp_path / "dqn.h").exists() and (tmp_path / "dqn.onnx").exists()
    assert export.main([str(policies / "dqn.policy"), "--c", str(tmp_path / "dqn.h")]) == 1
