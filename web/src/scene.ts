// The three.js side: one instanced star mesh built from GetScene, coloured by collision status,
// seen through the server's camera (orbit controls move a copy; reset brings it back).
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import type { SceneDescription } from "./gen/foveal/v1/foveal_pb";
import { peripheralStarGeometry, starDims, starGeometry } from "./star";

/** Colours of the legend, shared with the page's CSS swatches (see usePalette). */
export const COLOURS = {
  body: new THREE.Color(0x7f8ea3),
  real: new THREE.Color(0x2fbf71),
  /** Deemed colliding: wrong (truly apart, a visible gap) when audited, or not audited. */
  deemed: new THREE.Color(0xff4d4d),
  /** Deemed colliding and, by the frame's audit, truly touching: a right guess, nothing shows. */
  touching: new THREE.Color(0xb08d57),
  /** Deemed colliding in an audited frame whose audit passed the pair by (it samples). */
  unaudited: new THREE.Color(0xa58cc8),
  /** Every body but the pair in a close-up (see focusOn). */
  dimmed: new THREE.Color(0x2a3038),
  /** The body picked for inspection, and its pairs that are neither real nor deemed. */
  picked: new THREE.Color(0xffffff),
  separate: new THREE.Color(0x5c7cfa),
} as const;

/**
 * The two palettes of real and deemed: green and red, or for colour-blind viewers the
 * Okabe-Ito blue and orange (told apart under every common colour-vision deficiency).
 */
export const PALETTES = {
  standard: { real: 0x2fbf71, deemed: 0xff4d4d, touching: 0xb08d57, unaudited: 0xa58cc8, separate: 0x5c7cfa },
  "colour-blind": { real: 0x0072b2, deemed: 0xe69f00, touching: 0x56b4e9, unaudited: 0xf0e442, separate: 0xcc79a7 },
} as const;
export type PaletteName = keyof typeof PALETTES;

/** Switch the real and deemed colours (the caller recolours and updates the CSS swatches). */
export function usePalette(name: PaletteName): void {
  const p = PALETTES[name];
  COLOURS.real.set(p.real);
  COLOURS.deemed.set(p.deemed);
  COLOURS.touching.set(p.touching);
  COLOURS.unaudited.set(p.unaudited);
  COLOURS.separate.set(p.separate);
}

/** The camera's near plane, scene units (the server's camera and orbiting). */
const NEAR = 0.05;

export class SceneView {
  readonly renderer: THREE.WebGLRenderer;
  readonly scene = new THREE.Scene();
  readonly camera: THREE.PerspectiveCamera;
  readonly controls: OrbitControls;
  /**
   * Two instanced meshes of the star: the full tessellation (within 0.005R of the tested star)
   * for the bodies reaching into the foveal region, and a coarser one (within 0.035R, 56
   * triangles instead of 192) for the rest. On a CPU rasteriser a draw's cost grows with its triangles; what the
   * viewer looks at stays exact. Orbited or framed on a pair, every body gets the full one.
   */
  mesh: THREE.InstancedMesh | null = null;
  peripheral: THREE.InstancedMesh | null = null;
  /**
   * Where the full tessellation is drawn, in the server's screen coordinates (fractions of width
   * and height): an ellipse about the fixation. Null: everywhere.
   */
  detailRegion: { x: number; y: number; rx: number; ry: number } | null = null;
  /**
   * Thinning, for a browser that cannot draw every body at a usable rate: of the bodies outside
   * the detail region one in `farStride` is drawn (by body index, so the same bodies stay drawn
   * from frame to frame and a colour's share among them is what it is among all), while every body
   * reaching into the region is. 1: every body. Only where there is a region (the server's view
   * with a fixation).
   */
  farStride = 1;
  /** At the last split: bodies outside the detail region, and how many of them were drawn. */
  readonly farCounts = { far: 0, drawn: 0 };
  /** Every body's pose and colour as the frame gave them, before the split between the meshes. */
  private poses: Float32Array = new Float32Array(0);
  private bodies = 0;
  private radius = 0;
  private dirty = false;
  /** The server camera's view-projection matrix, for the split. */
  private homeViewProjection = new THREE.Matrix4();
  /** WebGL runs on the CPU (SwiftShader, llvmpipe): no GPU, as in headless browsers. */
  readonly software: boolean;
  /** The server's camera, for reset and for telling whether the view was orbited. */
  private home = { eye: new THREE.Vector3(), target: new THREE.Vector3() };
  private box: THREE.LineSegments | null = null;
  private colours: Float32Array = new Float32Array(0);
  /** Debug drawing: a line between the two bodies of each real and deemed pair. */
  private links: THREE.LineSegments;

  constructor(readonly canvas: HTMLCanvasElement) {
    // preserveDrawingBuffer: the page's tests read the canvas back to check it is drawn.
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
    const gl = this.renderer.getContext();
    const info = gl.getExtension("WEBGL_debug_renderer_info");
    const name = String(info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER));
    this.software = /swiftshader|llvmpipe|software/i.test(name);
    // On the CPU, presenting the canvas costs the page's main thread far more than drawing it:
    // fewer pixels keep input (the gaze) and the frame stream responsive.
    this.sharp(false);
    this.scene.background = new THREE.Color(0x101418);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x303040, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.5);
    sun.position.set(1, 2, 3);
    this.scene.add(sun);
    this.camera = new THREE.PerspectiveCamera(40, 1.6, NEAR, 1000);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = false;
    const lines = new THREE.BufferGeometry();
    lines.setAttribute("position", new THREE.BufferAttribute(new Float32Array(0), 3));
    lines.setAttribute("color", new THREE.BufferAttribute(new Float32Array(0), 3));
    this.links = new THREE.LineSegments(lines, new THREE.LineBasicMaterial({ vertexColors: true, depthTest: false, transparent: true, opacity: 0.9 }));
    this.links.frustumCulled = false;
    this.links.renderOrder = 1;
    this.links.visible = false;
    this.scene.add(this.links);
  }

  /**
   * Draw a line between the centres of the bodies of each pair (`pairs`: a, b, colour), from the
   * poses last written; an empty list (or `show` false) hides them.
   */
  setLinks(pairs: { a: number; b: number; c: THREE.Color }[], show: boolean): void {
    this.links.visible = show && pairs.length > 0;
    if (!this.links.visible) return;
    const g = this.links.geometry;
    let pos = g.getAttribute("position") as THREE.BufferAttribute;
    let col = g.getAttribute("color") as THREE.BufferAttribute;
    if (pos.count < 2 * pairs.length) {
      const n = 2 * Math.max(pairs.length, 2 * pos.count / 2);
      pos = new THREE.BufferAttribute(new Float32Array(3 * n), 3);
      col = new THREE.BufferAttribute(new Float32Array(3 * n), 3);
      pos.setUsage(THREE.DynamicDrawUsage);
      col.setUsage(THREE.DynamicDrawUsage);
      g.setAttribute("position", pos);
      g.setAttribute("color", col);
    }
    const p = pos.array as Float32Array, c = col.array as Float32Array, m = this.poses;
    let k = 0;
    for (const { a, b, c: colour } of pairs) {
      if (a >= this.bodies || b >= this.bodies) continue;
      for (const i of [a, b]) {
        p[3 * k] = m[16 * i + 12];
        p[3 * k + 1] = m[16 * i + 13];
        p[3 * k + 2] = m[16 * i + 14];
        c[3 * k] = colour.r;
        c[3 * k + 1] = colour.g;
        c[3 * k + 2] = colour.b;
        k++;
      }
    }
    g.setDrawRange(0, k);
    pos.needsUpdate = true;
    col.needsUpdate = true;
  }

  /**
   * The body under a point of the canvas (fractions of its width and height), through the camera
   * in use: the nearest whose bounding sphere the ray meets, or -1.
   */
  pickAt(x: number, y: number): number {
    const ray = new THREE.Raycaster();
    ray.setFromCamera(new THREE.Vector2(2 * x - 1, 1 - 2 * y), this.camera);
    const o = ray.ray.origin, d = ray.ray.direction, m = this.poses, r2 = this.radius * this.radius;
    let best = -1, nearest = Infinity;
    for (let i = 0; i < this.bodies; i++) {
      const cx = m[16 * i + 12] - o.x, cy = m[16 * i + 13] - o.y, cz = m[16 * i + 14] - o.z;
      const t = cx * d.x + cy * d.y + cz * d.z;
      if (t <= 0) continue;
      const off2 = cx * cx + cy * cy + cz * cz - t * t;
      if (off2 > r2) continue;
      const hit = t - Math.sqrt(r2 - off2);
      if (hit < nearest && hit > this.camera.near) (nearest = hit), (best = i);
    }
    return best;
  }

  /** A body's centre on the canvas (fractions of width and height), through the camera in use. */
  bodyOnScreen(i: number): { x: number; y: number } | null {
    if (i < 0 || i >= this.bodies) return null;
    const m = this.poses;
    return this.toScreen([m[16 * i + 12], m[16 * i + 13], m[16 * i + 14]]);
  }

  /**
   * Per body, its distance on the server's screen from (x, y) over the ellipse (rx, ry): below 1
   * inside the foveal region. What the schedulers' priority falls off with (priority shading).
   */
  eccentricities(x: number, y: number, rx: number, ry: number, out: Float32Array): void {
    const m = this.poses, e = this.homeViewProjection.elements;
    for (let i = 0; i < this.bodies && i < out.length; i++) {
      const o = 16 * i;
      const px = m[o + 12], py = m[o + 13], pz = m[o + 14];
      const w = e[3] * px + e[7] * py + e[11] * pz + e[15];
      if (w <= 0) {
        out[i] = Infinity;
        continue;
      }
      const dx = ((e[0] * px + e[4] * py + e[8] * pz + e[12]) / w + 1) / 2 - x;
      const dy = (1 - (e[1] * px + e[5] * py + e[9] * pz + e[13]) / w) / 2 - y;
      out[i] = Math.sqrt((dx / rx) ** 2 + (dy / ry) ** 2);
    }
  }

  /** Rebuild everything that depends on the scene: the mesh (N instances), camera and volume box. */
  load(d: SceneDescription): void {
    const cfg = d.config;
    const n = cfg?.bodies ?? 0;
    for (const old of [this.mesh, this.peripheral]) {
      if (!old) continue;
      this.scene.remove(old);
      old.geometry.dispose();
      old.dispose();
    }
    const material = new THREE.MeshLambertMaterial({ color: 0xffffff });
    const instanced = (geometry: THREE.BufferGeometry) => {
      const mesh = new THREE.InstancedMesh(geometry, material, n);
      mesh.instanceMatrix.setUsage(THREE.DynamicDrawUsage);
      mesh.frustumCulled = false;
      mesh.instanceColor = new THREE.InstancedBufferAttribute(new Float32Array(3 * n), 3);
      mesh.instanceColor.setUsage(THREE.DynamicDrawUsage);
      // Hidden until the first frame's poses arrive (identity matrices would stack at the origin).
      mesh.count = 0;
      this.scene.add(mesh);
      return mesh;
    };
    this.mesh = instanced(starGeometry(starDims(d)));
    this.peripheral = instanced(peripheralStarGeometry(starDims(d)));
    this.radius = starDims(d).radius;
    this.poses = new Float32Array(16 * n);
    this.colours = new Float32Array(3 * n);
    this.bodies = 0;

    const o = d.volumeOrigin ?? { x: 0, y: 0, z: 0 };
    const side = d.volumeSide;
    if (this.box) this.scene.remove(this.box);
    const box = new THREE.LineSegments(
      new THREE.EdgesGeometry(new THREE.BoxGeometry(side, side, side)),
      new THREE.LineBasicMaterial({ color: 0x3a4656 }),
    );
    box.position.set(o.x + side / 2, o.y + side / 2, o.z + side / 2);
    this.box = box;
    this.scene.add(box);

    const cam = d.camera;
    if (cam?.eye && cam.target) {
      this.home.eye.set(cam.eye.x, cam.eye.y, cam.eye.z);
      this.home.target.set(cam.target.x, cam.target.y, cam.target.z);
      this.camera.fov = cam.fovYDeg;
      this.camera.aspect = cam.aspect;
      this.camera.far = 10 * (side + this.home.eye.distanceTo(this.home.target));
    }
    this.resetView();
  }

  /**
   * Frame two bodies close up: orbit target at their midpoint, looking across the line between
   * their centres (so a gap between them is seen side on) from the side nearest the server's view
   * that no other body blocks, at a distance where their bounding sphere fills the height. Bodies
   * nearer the camera than the pair are clipped away. `centres` holds every body's centre
   * (x, y, z, stride 16: the instance matrices); `radius` is R.
   */
  focusOn(a: number, b: number, centres: Float32Array, radius: number): void {
    const at = (i: number) => new THREE.Vector3(centres[16 * i + 12], centres[16 * i + 13], centres[16 * i + 14]);
    const pa = at(a), pb = at(b);
    const mid = pa.clone().add(pb).multiplyScalar(0.5);
    const line = pb.clone().sub(pa);
    const reach = line.length() / 2 + radius; // the pair's bounding sphere about the midpoint
    const u = line.lengthSq() > 0 ? line.normalize() : new THREE.Vector3(1, 0, 0);
    const home = this.home.eye.clone().sub(this.home.target).normalize();
    let side = home.clone().addScaledVector(u, -home.dot(u));
    if (side.lengthSq() < 1e-6) side = new THREE.Vector3(0, 1, 0).cross(u);
    if (side.lengthSq() < 1e-6) side = new THREE.Vector3(0, 0, 1);
    side.normalize();
    const fov = THREE.MathUtils.degToRad(this.camera.fov);
    const distance = reach / Math.sin(fov / 2);
    // Candidate directions about the line of centres, nearest the server's view first; the first
    // with no other body in the cone of sight from the eye to the pair's bounding sphere wins
    // (else the least blocked). Directions nearly along "up" are skipped (orbiting needs an up).
    const n = centres.length / 16;
    let best = side.clone(), fewest = Infinity;
    for (let k = 0; k < 24 && fewest > 0; k++) {
      const angle = (k % 2 ? -1 : 1) * Math.ceil(k / 2) * (Math.PI / 12);
      const dir = side.clone().applyAxisAngle(u, angle);
      if (Math.abs(dir.y) > 0.95) continue;
      const eye = mid.clone().addScaledVector(dir, distance);
      let blocked = 0;
      for (let i = 0; i < n; i++) {
        if (i === a || i === b) continue;
        const c = at(i).sub(eye);
        const t = -c.dot(dir) / distance; // 0 at the eye, 1 at the midpoint
        if (t <= 0 || t >= 1) continue;
        const off = c.addScaledVector(dir, t * distance).length();
        if (off < radius + reach * t) blocked++;
      }
      if (blocked < fewest) (fewest = blocked), (best = dir);
    }
    this.camera.position.copy(mid).addScaledVector(best, distance);
    this.controls.target.copy(mid);
    this.camera.near = Math.max(0.01, distance - reach - 0.05 * radius);
    this.camera.up.set(0, 1, 0);
    this.camera.lookAt(mid);
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.focused = true;
    this.sharp(true);
  }

  /** A world point on the canvas, as fractions of its width and height (0, 0 top left). */
  toScreen(p: number[]): { x: number; y: number } {
    const v = new THREE.Vector3(p[0], p[1], p[2]).project(this.camera);
    return { x: (v.x + 1) / 2, y: (1 - v.y) / 2 };
  }

  private wasOrbited = false;

  /** Whether the view is framed on a pair (focusOn) rather than the server's or an orbited camera. */
  focused = false;

  /** Back to the server's camera, the one gaze coordinates and P are measured through. */
  resetView(): void {
    if (this.focused) this.sharp(false);
    this.focused = false;
    this.camera.near = NEAR;
    this.camera.position.copy(this.home.eye);
    this.controls.target.copy(this.home.target);
    this.camera.up.set(0, 1, 0);
    this.camera.lookAt(this.home.target);
    this.camera.updateProjectionMatrix();
    this.controls.update();
    this.camera.updateMatrixWorld();
    this.homeViewProjection.multiplyMatrices(this.camera.projectionMatrix, this.camera.matrixWorldInverse);
    this.dirty = true;
  }

  /** Whether the user orbited away from the server's camera. */
  orbited(): boolean {
    return (
      this.camera.position.distanceToSquared(this.home.eye) > 1e-6 ||
      this.controls.target.distanceToSquared(this.home.target) > 1e-6
    );
  }

  /**
   * Look through `other`'s camera (the side by side's right view follows the left one, which
   * the user orbits).
   */
  followCamera(other: SceneView): void {
    const moved =
      this.camera.position.distanceToSquared(other.camera.position) > 0 ||
      this.controls.target.distanceToSquared(other.controls.target) > 0 ||
      this.camera.near !== other.camera.near;
    if (!moved) return;
    this.camera.position.copy(other.camera.position);
    this.camera.quaternion.copy(other.camera.quaternion);
    this.camera.up.copy(other.camera.up);
    this.camera.near = other.camera.near;
    this.controls.target.copy(other.controls.target);
    this.camera.updateProjectionMatrix();
    this.dirty = true;
  }

  /** The instance matrices to write a frame's poses into. */
  matrices(): Float32Array {
    return this.poses;
  }

  /** Mark `bodies` matrices as written. */
  posesWritten(bodies: number): void {
    this.bodies = bodies;
    this.dirty = true;
  }

  /** Hand what changed since the last call (poses, colours, detail region) to the meshes. */
  commit(): void {
    if (!this.dirty) return;
    this.split();
    this.dirty = false;
  }

  /** Draw one in `k` of the bodies outside the detail region (see farStride). */
  setFarStride(k: number): void {
    const stride = Math.max(1, Math.floor(k));
    if (stride === this.farStride) return;
    this.farStride = stride;
    this.dirty = true;
  }

  /** Where the full tessellation is drawn (see detailRegion). */
  setDetailRegion(r: { x: number; y: number; rx: number; ry: number } | null): void {
    const o = this.detailRegion;
    if (o === r || (o && r && o.x === r.x && o.y === r.y && o.rx === r.rx && o.ry === r.ry)) return;
    this.detailRegion = r;
    this.dirty = true;
  }

  /**
   * Copy each body's pose and colour into the mesh it is drawn with: the full one when it reaches
   * into the detail region as the server's camera sees it (its centre within the region widened
   * by the body's bounding radius on screen), the peripheral one otherwise.
   */
  private split(): void {
    const fine = this.mesh, coarse = this.peripheral;
    if (!fine?.instanceColor || !coarse?.instanceColor) return;
    const m = this.poses, col = this.colours, e = this.homeViewProjection.elements;
    const region = this.orbited() ? null : this.detailRegion;
    const out = [fine, coarse].map((mesh) => ({
      m: mesh.instanceMatrix.array as Float32Array,
      c: mesh.instanceColor!.array as Float32Array,
      n: 0,
    }));
    const stride = region ? this.farStride : 1;
    let far = 0, farDrawn = 0;
    for (let i = 0; i < this.bodies; i++) {
      const o = 16 * i;
      let near = true;
      if (region) {
        const x = m[o + 12], y = m[o + 13], z = m[o + 14];
        const w = e[3] * x + e[7] * y + e[11] * z + e[15];
        if (w <= 0) near = false;
        else {
          const dx = ((e[0] * x + e[4] * y + e[8] * z + e[12]) / w + 1) / 2 - region.x;
          const dy = (1 - (e[1] * x + e[5] * y + e[9] * z + e[13]) / w) / 2 - region.y;
          // R on screen, as fractions of width and height (half the projection's scale at depth w).
          const rx = region.rx + (e[0] * this.radius) / (2 * w), ry = region.ry + (e[5] * this.radius) / (2 * w);
          near = (dx / rx) ** 2 + (dy / ry) ** 2 <= 1;
        }
      }
      if (!near) {
        far++;
        if (i % stride !== 0) continue;
        farDrawn++;
      }
      const t = out[near ? 0 : 1];
      const to = 16 * t.n;
      for (let k = 0; k < 16; k++) t.m[to + k] = m[o + k];
      t.c[3 * t.n] = col[3 * i];
      t.c[3 * t.n + 1] = col[3 * i + 1];
      t.c[3 * t.n + 2] = col[3 * i + 2];
      t.n++;
    }
    this.farCounts.far = far;
    this.farCounts.drawn = farDrawn;
    [fine, coarse].forEach((mesh, k) => {
      mesh.count = out[k].n;
      mesh.instanceMatrix.needsUpdate = true;
      mesh.instanceColor!.needsUpdate = true;
    });
  }

  /**
   * Colour every body: the plain colour (or COLOURS.dimmed with `dimmed`), then the real and
   * deemed pairs' bodies.
   */
  colour(
    marks: (set: (body: number, c: THREE.Color) => void) => void,
    dimmed = false,
    shade: ((body: number) => number) | null = null,
  ): void {
    const col = this.colours;
    const { r, g, b } = dimmed ? COLOURS.dimmed : COLOURS.body;
    for (let i = 0; i < col.length; i += 3) {
      // Priority shading: the plain colour scaled by a factor per body (1 where the viewer looks).
      const k = shade ? shade(i / 3) : 1;
      col[i] = r * k;
      col[i + 1] = g * k;
      col[i + 2] = b * k;
    }
    const n = col.length / 3;
    marks((body, c) => {
      if (body < n) {
        col[3 * body] = c.r;
        col[3 * body + 1] = c.g;
        col[3 * body + 2] = c.b;
      }
    });
    this.dirty = true;
  }

  /** A body's colour as last set (r, g, b in 0..1): what the browser tests read instead of pixels. */
  colourOf(body: number): number[] {
    return Array.from(this.colours.subarray(3 * body, 3 * body + 3));
  }

  /**
   * Draw at the display's full resolution even on a CPU rasteriser, for a close-up (a held frame:
   * the page's input and frame stream matter less there than a picture sharp enough to judge a
   * gap by), or back to the usual resolution.
   */
  sharp(on: boolean): void {
    const full = Math.min(window.devicePixelRatio, 2);
    this.renderer.setPixelRatio(on || !this.software ? full : 0.5);
  }

  /** Fit the drawing buffer to the canvas's CSS size. */
  resize(width: number, height: number): void {
    this.renderer.setSize(width, height, false);
  }

  render(): void {
    if (this.controls.enabled) this.controls.update();
    // Orbiting changes which mesh a body needs (every body gets the full one off the server's view).
    const orbited = this.orbited();
    if (orbited !== this.wasOrbited) (this.wasOrbited = orbited), (this.dirty = true);
    this.commit();
    this.renderer.render(this.scene, this.camera);
  }
}
