// The 3D view of a recorded episode: every Scene primitive (core/scene.hpp) drawn with three.js
// in the lab frame (metres), coloured by role, with an orbiting camera.
import * as THREE from 'three';
import { OrbitControls } from 'three/addons/controls/OrbitControls.js';

const roleColours = {
  arm: 0xe07b39,
  rod: 0xe07b39,
  target: 0xd62728,
  goal: 0x2ca02c,
  obstacle: 0x6c7a89,
  wall: 0x6c7a89,
  ground: 0xb8c4a8,
  path: 0x1f77b4,
  reference: 0x1f77b4,
};

export function roleColour(role) {
  if (role in roleColours) return roleColours[role];
  let hash = 0;
  for (const c of role) hash = (hash * 31 + c.charCodeAt(0)) | 0;
  return new THREE.Color().setHSL(((hash >>> 0) % 360) / 360, 0.55, 0.5).getHex();
}

const unitY = new THREE.Vector3(0, 1, 0);
const unitZ = new THREE.Vector3(0, 0, 1);

function vec(a, i = 0) {
  return new THREE.Vector3(a[i], a[i + 1], a[i + 2]);
}

// Places a unit cylinder (axis y, radius 1, height 1) from a to b with radius r.
function placeCylinder(mesh, a, b, r) {
  const axis = new THREE.Vector3().subVectors(b, a);
  const length = axis.length();
  mesh.position.copy(a).addScaledVector(axis, 0.5);
  if (length > 0) mesh.quaternion.setFromUnitVectors(unitY, axis.divideScalar(length));
  mesh.scale.set(r, Math.max(length, 1e-9), r);
}

// A pool of objects of one kind, grown on demand; those not used in a frame are hidden.
class Pool {
  constructor(parent, create) {
    this.parent = parent;
    this.create = create;
    this.items = [];
  }
  get(i, role) {
    while (this.items.length <= i) {
      const item = this.create(role);
      this.parent.add(item);
      this.items.push(item);
    }
    this.items[i].visible = true;
    return this.items[i];
  }
  hideFrom(n) {
    for (let i = n; i < this.items.length; i++) this.items[i].visible = false;
  }
}

function material(role, options = {}) {
  return new THREE.MeshStandardMaterial({
    color: roleColour(role),
    roughness: 0.55,
    metalness: 0.05,
    ...options,
  });
}

const cylinderGeometry = new THREE.CylinderGeometry(1, 1, 1, 20, 1);
const sphereGeometry = new THREE.SphereGeometry(1, 24, 16);
const boxGeometry = new THREE.BoxGeometry(1, 1, 1);

// The bounds of everything drawn in any frame.
export function episodeBounds(episode) {
  const box = new THREE.Box3();
  const add = (x, y, z) => box.expandByPoint(new THREE.Vector3(x, y, z));
  const addPoints = (p) => {
    for (let i = 0; i + 2 < p.length; i += 3) add(p[i], p[i + 1], p[i + 2]);
  };
  for (const frame of episode.frames) {
    const s = frame.scene;
    s.rods.forEach((r) => addPoints(r.points));
    s.spheres.forEach((o) => addPoints(o.centre));
    s.cylinders.forEach((o) => {
      addPoints(o.start);
      addPoints(o.end);
    });
    s.boxes.forEach((o) => addPoints(o.centre));
    s.lattices.forEach((o) => addPoints(o.nodes));
    s.paths.forEach((o) => addPoints(o.points));
  }
  if (box.isEmpty()) box.set(new THREE.Vector3(-1, -1, -1), new THREE.Vector3(1, 1, 1));
  return box;
}

// A round grid spacing near `length` / 8: 1, 2 or 5 times a power of ten (as tendril's own
// pictures, render/camera.cpp).
export function gridSpacing(length) {
  const raw = Math.max(length, 1e-6) / 8;
  const power = 10 ** Math.floor(Math.log10(raw));
  for (const factor of [1, 2, 5]) if (factor * power >= raw) return factor * power;
  return 10 * power;
}

// The lab axis to draw upwards: the one the first rod runs along from base to tip (PyElastica's
// arms grow along y), else z.
export function detectUp(episode) {
  const rod = episode.frames[0]?.scene.rods[0];
  if (!rod || rod.points.length < 6) return 'z';
  const n = rod.points.length;
  const span = [0, 1, 2].map((c) => Math.abs(rod.points[n - 3 + c] - rod.points[c]));
  return span[1] > span[2] && span[1] >= span[0] ? 'y' : 'z';
}

export class SceneView {
  constructor(container, episode) {
    this.container = container;
    this.episode = episode;
    this.bounds = episodeBounds(episode);
    this.size = Math.max(this.bounds.getSize(new THREE.Vector3()).length(), 0.1);

    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio || 1);
    this.renderer.setClearColor(0xf4f5f7);
    container.appendChild(this.renderer.domElement);

    this.scene = new THREE.Scene();
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x667788, 1.6));
    const sun = new THREE.DirectionalLight(0xffffff, 1.6);
    sun.position.set(1, 2, 3);
    this.scene.add(sun);

    this.camera = new THREE.PerspectiveCamera(40, 1, this.size / 1000, this.size * 100);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.enableDamping = true;

    this.content = new THREE.Group();
    this.scene.add(this.content);
    this.pools = {
      segments: new Pool(this.content, (role) => new THREE.Mesh(cylinderGeometry, material(role))),
      joints: new Pool(this.content, (role) => new THREE.Mesh(sphereGeometry, material(role))),
      spheres: new Pool(this.content, (role) => new THREE.Mesh(sphereGeometry, material(role))),
      cylinders: new Pool(
        this.content,
        (role) => new THREE.Mesh(cylinderGeometry, material(role, { transparent: true, opacity: 0.85 })),
      ),
      caps: new Pool(this.content, (role) => new THREE.Mesh(sphereGeometry, material(role))),
      boxes: new Pool(
        this.content,
        (role) => new THREE.Mesh(boxGeometry, material(role, { transparent: true, opacity: 0.85 })),
      ),
      planes: new Pool(
        this.content,
        (role) =>
          new THREE.Mesh(
            new THREE.PlaneGeometry(1, 1),
            material(role, { transparent: true, opacity: 0.35, side: THREE.DoubleSide }),
          ),
      ),
      latticeNodes: new Pool(this.content, (role) => new THREE.Mesh(sphereGeometry, material(role))),
      lines: new Pool(this.content, () => {
        const line = new THREE.LineSegments(
          new THREE.BufferGeometry(),
          new THREE.LineBasicMaterial({ color: 0x333333 }),
        );
        line.frustumCulled = false;
        return line;
      }),
    };
    this.trails = this.buildTrails();
    this.grid = null;
    this.axes = null;
    this.setUp(detectUp(episode));
    this.frameIndex = 0;
    this.show(0);

    this.resizer = new ResizeObserver(() => this.resize());
    this.resizer.observe(container);
    this.resize();
    const loop = () => {
      this.animation = requestAnimationFrame(loop);
      this.controls.update();
      this.renderer.render(this.scene, this.camera);
    };
    loop();
  }

  // The paths of each target sphere and of each rod's tip over the whole episode, drawn up to
  // the current frame.
  buildTrails() {
    const trails = [];
    const first = this.episode.frames[0]?.scene;
    if (!first) return trails;
    const collect = (pick) =>
      this.episode.frames.map((f) => pick(f.scene)).filter((p) => p !== null);
    first.spheres.forEach((sphere, i) => {
      if (sphere.role !== 'target' && sphere.role !== 'goal') return;
      const points = collect((s) => (s.spheres[i] ? vec(s.spheres[i].centre) : null));
      trails.push(this.trailLine(points, roleColour(sphere.role)));
    });
    first.rods.forEach((rod, i) => {
      const points = collect((s) => {
        const r = s.rods[i];
        return r ? vec(r.points, r.points.length - 3) : null;
      });
      trails.push(this.trailLine(points, roleColour(rod.role)));
    });
    return trails;
  }

  trailLine(points, colour) {
    const geometry = new THREE.BufferGeometry().setFromPoints(points);
    const line = new THREE.Line(
      geometry,
      new THREE.LineBasicMaterial({ color: colour, transparent: true, opacity: 0.6 }),
    );
    line.frustumCulled = false;
    this.scene.add(line);
    return line;
  }

  // Which lab axis points up on screen: 'z' (the Elastica arms grow along z) or 'y'. The floor
  // is a grid under everything drawn (at the lab's zero height or below), centred under the
  // episode, its lines a round distance apart (about an eighth of the scene) and through the lab
  // origin; an axis triad (x red, y green, z blue) two grid lines long marks the origin.
  setUp(axis) {
    this.up = axis;
    this.camera.up.copy(axis === 'z' ? unitZ : unitY);
    if (this.grid) this.scene.remove(this.grid);
    if (this.axes) this.scene.remove(this.axes);
    const spacing = gridSpacing(this.size);
    const centre = this.bounds.getCenter(new THREE.Vector3());
    const half = Math.ceil((0.6 * this.size) / spacing) * spacing;
    const snap = (v) => Math.round(v / spacing) * spacing;
    this.grid = new THREE.GridHelper(2 * half, Math.round((2 * half) / spacing), 0xaab0b8, 0xd5d9de);
    if (axis === 'z') {
      this.grid.rotation.x = Math.PI / 2;
      this.grid.position.set(snap(centre.x), snap(centre.y), Math.min(this.bounds.min.z, 0));
    } else {
      this.grid.position.set(snap(centre.x), Math.min(this.bounds.min.y, 0), snap(centre.z));
    }
    this.scene.add(this.grid);
    this.axes = new THREE.AxesHelper(2 * spacing);
    this.axes.material.depthTest = false;  // drawn over the floor it stands on
    this.axes.renderOrder = 1;
    this.scene.add(this.axes);
    this.resetCamera();
  }

  resetCamera() {
    const centre = this.bounds.getCenter(new THREE.Vector3());
    const distance = this.size * 1.6 + 0.2;
    const direction =
      this.up === 'z' ? new THREE.Vector3(1.0, -1.4, 0.7) : new THREE.Vector3(1.0, 0.7, 1.4);
    this.camera.position.copy(centre).addScaledVector(direction.normalize(), distance);
    this.controls.target.copy(centre);
    this.controls.update();
  }

  resize() {
    const width = Math.max(this.container.clientWidth, 200);
    const height = Math.max(this.container.clientHeight, 200);
    this.renderer.setSize(width, height);
    this.camera.aspect = width / height;
    this.camera.updateProjectionMatrix();
  }

  show(frameIndex) {
    const frame = this.episode.frames[frameIndex];
    if (!frame) return;
    this.frameIndex = frameIndex;
    const s = frame.scene;
    const p = this.pools;
    const used = { segments: 0, joints: 0, spheres: 0, cylinders: 0, caps: 0, boxes: 0,
                   planes: 0, latticeNodes: 0, lines: 0 };
    const take = (kind, role) => p[kind].get(used[kind]++, role);

    for (const rod of s.rods) {
      const nodes = [];
      for (let i = 0; i + 2 < rod.points.length; i += 3) nodes.push(vec(rod.points, i));
      const radius = (k) => rod.radii[Math.min(k, rod.radii.length - 1)] ?? 0.01;
      for (let k = 0; k + 1 < nodes.length; k++) {
        placeCylinder(take('segments', rod.role), nodes[k], nodes[k + 1], radius(k));
      }
      nodes.forEach((node, k) => {
        const joint = take('joints', rod.role);
        joint.position.copy(node);
        joint.scale.setScalar(Math.max(radius(Math.max(k - 1, 0)), radius(k)));
      });
    }
    for (const sphere of s.spheres) {
      const mesh = take('spheres', sphere.role);
      mesh.position.copy(vec(sphere.centre));
      mesh.scale.setScalar(Math.max(sphere.radius, 1e-6));
    }
    for (const cylinder of s.cylinders) {
      const a = vec(cylinder.start);
      const b = vec(cylinder.end);
      placeCylinder(take('cylinders', cylinder.role), a, b, cylinder.radius);
      if (cylinder.capped) {
        for (const end of [a, b]) {
          const cap = take('caps', cylinder.role);
          cap.position.copy(end);
          cap.scale.setScalar(cylinder.radius);
        }
      }
    }
    for (const box of s.boxes) {
      const mesh = take('boxes', box.role);
      mesh.position.copy(vec(box.centre));
      const [w, x, y, z] = box.orientation;
      mesh.quaternion.set(x, y, z, w).normalize();
      mesh.scale.set(2 * box.half_extents[0], 2 * box.half_extents[1], 2 * box.half_extents[2]);
    }
    for (const plane of s.planes) {
      const mesh = take('planes', plane.role);
      mesh.position.copy(vec(plane.point));
      mesh.quaternion.setFromUnitVectors(unitZ, vec(plane.normal).normalize());
      mesh.scale.setScalar(this.size * 1.5);
    }
    for (const lattice of s.lattices) {
      const nodeRadius = this.size * 0.006;
      const springs = this.episode.springs[lattice.springs] || [];
      for (let i = 0; i + 2 < lattice.nodes.length; i += 3) {
        const node = take('latticeNodes', lattice.role);
        node.position.copy(vec(lattice.nodes, i));
        node.scale.setScalar(nodeRadius);
      }
      const positions = new Float32Array(springs.length * 6);
      springs.forEach(([a, b], k) => {
        for (let c = 0; c < 3; c++) {
          positions[6 * k + c] = lattice.nodes[3 * a + c];
          positions[6 * k + 3 + c] = lattice.nodes[3 * b + c];
        }
      });
      const line = take('lines', lattice.role);
      line.geometry.setAttribute('position', new THREE.BufferAttribute(positions, 3));
      line.material.color.set(roleColour(lattice.role));
    }
    for (const path of s.paths) {
      const positions = [];
      for (let i = 0; i + 5 < path.points.length; i += 3) {
        positions.push(...path.points.slice(i, i + 6));
      }
      const line = take('lines', path.role);
      line.geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
      line.material.color.set(roleColour(path.role));
    }
    for (const kind of Object.keys(p)) p[kind].hideFrom(used[kind]);
    for (const trail of this.trails) trail.geometry.setDrawRange(0, frameIndex + 1);
  }

  dispose() {
    cancelAnimationFrame(this.animation);
    this.resizer.disconnect();
    this.controls.dispose();
    this.renderer.dispose();
    this.renderer.domElement.remove();
  }
}
