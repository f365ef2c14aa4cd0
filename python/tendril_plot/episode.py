"""Reader of recorded episode files (.tep, docs/episode_format.md) with NumPy only.

    episode = read_episode("runs/x/episodes/episode_0000.tep")
    episode.frames[10]["rods"][0]["points"]   # (N, 3) centreline in metres, lab frame

Every record's CRC-32 is checked. A damaged or unfinished file raises EpisodeError, or, with
partial=True, gives the whole frames before the problem and names it in `episode.problem`.
"""
import struct
import zlib

import numpy as np

MAGIC = b"tendril-episode\n"
VERSION = 1
KINDS = {1: "rods", 2: "spheres", 3: "cylinders", 4: "boxes", 5: "planes", 6: "lattices", 7: "paths"}
KIND_ORDER = ["rods", "spheres", "cylinders", "boxes", "planes", "lattices", "paths"]


class EpisodeError(ValueError):
    pass


class Episode:
    def __init__(self):
        self.metadata = {}
        self.action_size = 0
        self.frames = []
        self.summary = None  # dict(steps, episode_return, terminated, truncated) when finished
        self.problem = ""  # empty when complete and intact
        self.truncated = False

    def times(self):
        return np.array([f["time"] for f in self.frames])

    def rewards(self):
        return np.array([f["reward"] for f in self.frames])

    def info(self, name):
        return np.array([f["info"].get(name, np.nan) for f in self.frames])


class _Cursor:
    def __init__(self, data):
        self.data = data
        self.at = 0

    def take(self, fmt):
        size = struct.calcsize(fmt)
        if self.at + size > len(self.data):
            raise EpisodeError("record ends inside a field")
        values = struct.unpack_from(fmt, self.data, self.at)
        self.at += size
        return values

    def u8(self):
        return self.take("<B")[0]

    def u32(self):
        return self.take("<I")[0]

    def f64(self):
        return self.take("<d")[0]

    def text(self):
        n = self.u32()
        if self.at + n > len(self.data):
            raise EpisodeError("a string longer than its record")
        value = self.data[self.at:self.at + n].decode("utf-8")
        self.at += n
        return value

    def floats(self, n):
        if self.at + 4 * n > len(self.data):
            raise EpisodeError("record ends inside its numbers")
        values = np.frombuffer(self.data, dtype="<f4", count=n, offset=self.at).astype(np.float64)
        self.at += 4 * n
        return values


def _float_count(p):
    kind = p["kind"]
    if kind == "rods":
        return 3 * p["points"] + p["radii"]
    return {"spheres": 4, "cylinders": 7, "boxes": 10, "planes": 6}.get(kind, 3 * p.get("points", 0))


def _layout(c):
    layout = {"action_size": c.u32()}
    layout["info"] = [c.text() for _ in range(c.u32())]
    layout["values"] = [c.text() for _ in range(c.u32())]
    primitives = []
    for _ in range(c.u32()):
        code = c.u8()
        if code not in KINDS:
            raise EpisodeError(f"unknown primitive kind {code}")
        p = {"kind": KINDS[code], "role": c.text()}
        if p["kind"] == "rods":
            p["points"], p["radii"] = c.u32(), c.u32()
        elif p["kind"] == "cylinders":
            p["capped"] = c.u8() != 0
        elif p["kind"] == "lattices":
            p["points"] = c.u32()
            n = c.u32()
            p["springs"] = np.array(c.take(f"<{2 * n}I"), dtype=np.int64).reshape(n, 2)
        elif p["kind"] == "paths":
            p["points"] = c.u32()
        primitives.append(p)
    layout["primitives"] = primitives
    return layout


def _primitive(p, data):
    kind, role = p["kind"], p["role"]
    if kind == "rods":
        n = p["points"]
        return {"role": role, "points": data[:3 * n].reshape(n, 3), "radii": data[3 * n:]}
    if kind == "spheres":
        return {"role": role, "centre": data[:3], "radius": data[3]}
    if kind == "cylinders":
        return {"role": role, "start": data[:3], "end": data[3:6], "radius": data[6],
                "capped": p["capped"]}
    if kind == "boxes":
        return {"role": role, "centre": data[:3], "half_extents": data[3:6],
                "orientation": data[6:10]}  # w, x, y, z
    if kind == "planes":
        return {"role": role, "point": data[:3], "normal": data[3:6]}
    if kind == "lattices":
        return {"role": role, "nodes": data.reshape(-1, 3), "springs": p["springs"]}
    return {"role": role, "points": data.reshape(-1, 3)}


def read_episode(path, partial=False):
    with open(path, "rb") as f:
        data = f.read()
    if not data.startswith(MAGIC):
        raise EpisodeError(f"{path}: not an episode file (no 'tendril-episode' magic)")
    episode = Episode()
    at = len(MAGIC)
    layout, latest, has_header = None, [], False

    def stop(problem, truncated):
        episode.problem = f"{problem} at byte {at}"
        episode.truncated = truncated

    while True:
        if episode.summary is not None:
            if at != len(data):
                stop("bytes after the end record", False)
            break
        left = len(data) - at
        if left == 0:
            stop("no end record (the recording is unfinished or was cut off)", True)
            break
        if left < 5:
            stop("the file ends inside a record", True)
            break
        tag, length = struct.unpack_from("<BI", data, at)
        if left < 9 + length:
            stop("the file ends inside a record", True)
            break
        (stored,) = struct.unpack_from("<I", data, at + 5 + length)
        if zlib.crc32(data[at:at + 5 + length]) != stored:
            stop("checksum mismatch in a record", False)
            break
        c = _Cursor(data[at + 5:at + 5 + length])
        try:
            tag = chr(tag)
            if not has_header and tag != "H":
                raise EpisodeError("the first record is no header")
            if tag == "H":
                version = c.u32()
                if version > VERSION:
                    raise EpisodeError(f"format version {version} is newer than this reader's")
                for _ in range(c.u32()):
                    key = c.text()
                    episode.metadata[key] = c.text()
                has_header = True
            elif tag == "L":
                layout = _layout(c)
                episode.action_size = layout["action_size"]
                latest = [None] * len(layout["primitives"])
            elif tag == "F":
                if layout is None:
                    raise EpisodeError("a frame before any layout record")
                step, time, reward, flags = c.take("<IddB")
                action = c.floats(layout["action_size"])
                info = dict(zip(layout["info"], c.floats(len(layout["info"]))))
                values = dict(zip(layout["values"], c.floats(len(layout["values"]))))
                n = len(layout["primitives"])
                mask = c.take(f"<{(n + 7) // 8}B")
                for i, p in enumerate(layout["primitives"]):
                    if mask[i // 8] >> (i % 8) & 1:
                        latest[i] = c.floats(_float_count(p))
                    elif latest[i] is None:
                        raise EpisodeError(f"primitive {i} never written")
                if c.at != len(c.data):
                    raise EpisodeError("a frame record longer than its layout")
                frame = {"step": step, "time": time, "reward": reward,
                         "terminated": bool(flags & 1), "truncated": bool(flags & 2),
                         "action": None if np.all(np.isnan(action)) else action,
                         "info": {k: v for k, v in info.items() if not np.isnan(v)},
                         "values": values}
                for kind in KIND_ORDER:
                    frame[kind] = []
                for p, d in zip(layout["primitives"], latest):
                    frame[p["kind"]].append(_primitive(p, d))
                episode.frames.append(frame)
            elif tag == "E":
                steps, total, flags = c.take("<IdB")
                episode.summary = {"steps": steps, "episode_return": total,
                                   "terminated": bool(flags & 1), "truncated": bool(flags & 2)}
            else:
                raise EpisodeError(f"unknown record tag {ord(tag)}")
        except (EpisodeError, struct.error, UnicodeDecodeError) as e:
            if not has_header:
                raise EpisodeError(f"{path}: unreadable header: {e}")
            stop(str(e), False)
            break
        at += 9 + length
    if not has_header:
        raise EpisodeError(f"{path}: unreadable header: {episode.problem}")
    if episode.problem and not partial:
        raise EpisodeError(f"{path}: {episode.problem}")
    return episode
