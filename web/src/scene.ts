// The three.js side: one instanced star mesh built from GetScene, coloured by collision status,
// seen through the server's camera (orbit controls move a copy; reset brings it back).
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import type { SceneDescription } from "./gen/foveal/v1/foveal_pb";
import { starDims, starGeometry } from "./star";

/** Colours of the legend, shared with the page's CSS swatches. */
export const COLOURS = {
  body: new THREE.Color(0x7f8ea3),
  real: new THREE.Color(0x2fbf71),
  deemed: new THREE.Color(0xff4d4d),
} as const;

export class SceneView {
  readonly renderer: THREE.WebGLRenderer;
  readonly scene = new THREE.Scene();
  readonly camera: THREE.PerspectiveCamera;
  readonly controls: OrbitControls;
  mesh: THREE.InstancedMesh | null = null;
  /** WebGL runs on the CPU (SwiftShader, llvmpipe): no GPU, as in headless browsers. */
  readonly software: boolean;
  /** The server's camera, for reset and for telling whether the view was orbited. */
  private home = { eye: new THREE.Vector3(), target: new THREE.Vector3() };
  private box: THREE.LineSegments | null = null;
  private colours: Float32Array = new Float32Array(0);

  constructor(readonly canvas: HTMLCanvasElement) {
    // preserveDrawingBuffer: the page's tests read the canvas back to check it is drawn.
    this.renderer = new THREE.WebGLRenderer({ canvas, antialias: false, preserveDrawingBuffer: true });
    const gl = this.renderer.getContext();
    const info = gl.getExtension("WEBGL_debug_renderer_info");
    const name = String(info ? gl.getParameter(info.UNMASKED_RENDERER_WEBGL) : gl.getParameter(gl.RENDERER));
    this.software = /swiftshader|llvmpipe|software/i.test(name);
    // On the CPU, presenting the canvas costs the page's main thread far more than drawing it:
    // fewer pixels keep input (the gaze) and the frame stream responsive.
    this.renderer.setPixelRatio(this.software ? 0.5 : Math.min(window.devicePixelRatio, 2));
    this.scene.background = new THREE.Color(0x101418);
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x303040, 2.2));
    const sun = new THREE.DirectionalLight(0xffffff, 1.5);
    sun.position.set(1, 2, 3);
    this.scene.add(sun);
    this.camera = new THREE.PerspectiveCamera(40, 1.6, 0.05, 1000);
    this.controls = new OrbitControls(this.camera, canvas);
    this.controls.enableDamping = false;
  }

  /** Rebuild everything that depends on the scene: the mesh (N instances), camera and volume box. */
  load(d: SceneDescription): void {
    const cfg = d.config;
    const n = cfg?.bodies ?? 0;
    if (this.mesh) {
      this.scene.remove(this.mesh);
      this.mesh.geometry.dispose();
      this.mesh.dispose();
    }
    const material = new THREE.MeshLambertMaterial({ color: 0xffffff });
    const mesh = new THREE.InstancedMesh(starGeometry(starDims(d)), material, n);
    mesh.instanceMatrix.setUsage(THREE.DynamicDrawUsage);
    mesh.frustumCulled = false;
    this.colours = new Float32Array(3 * n);
    mesh.instanceColor = new THREE.InstancedBufferAttribute(this.colours, 3);
    mesh.instanceColor.setUsage(THREE.DynamicDrawUsage);
    // Hidden until the first frame's poses arrive (identity matrices would stack at the origin).
    mesh.count = 0;
    this.mesh = mesh;
    this.scene.add(mesh);

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

  /** Back to the server's camera, the one gaze coordinates and P are measured through. */
  resetView(): void {
    this.camera.position.copy(this.home.eye);
    this.controls.target.copy(this.home.target);
    this.camera.up.set(0, 1, 0);
    this.camera.lookAt(this.home.target);
    this.camera.updateProjectionMatrix();
    this.controls.update();
  }

  /** Whether the user orbited away from the server's camera. */
  orbited(): boolean {
    return (
      this.camera.position.distanceToSquared(this.home.eye) > 1e-6 ||
      this.controls.target.distanceToSquared(this.home.target) > 1e-6
    );
  }

  /** The instance matrices to write a frame's poses into. */
  matrices(): Float32Array {
    return this.mesh ? (this.mesh.instanceMatrix.array as Float32Array) : new Float32Array(0);
  }

  /** Mark `bodies` matrices as written. */
  posesWritten(bodies: number): void {
    if (!this.mesh) return;
    this.mesh.count = bodies;
    this.mesh.instanceMatrix.needsUpdate = true;
  }

  /** Colour every body: the plain colour, then the real and deemed pairs' bodies. */
  colour(marks: (set: (body: number, c: THREE.Color) => void) => void): void {
    const col = this.colours;
    const { r, g, b } = COLOURS.body;
    for (let i = 0; i < col.length; i += 3) {
      col[i] = r;
      col[i + 1] = g;
      col[i + 2] = b;
    }
    const n = col.length / 3;
    marks((body, c) => {
      if (body < n) {
        col[3 * body] = c.r;
        col[3 * body + 1] = c.g;
        col[3 * body + 2] = c.b;
      }
    });
    if (this.mesh?.instanceColor) this.mesh.instanceColor.needsUpdate = true;
  }

  /** Fit the drawing buffer to the canvas's CSS size. */
  resize(width: number, height: number): void {
    this.renderer.setSize(width, height, false);
  }

  render(): void {
    this.controls.update();
    this.renderer.render(this.scene, this.camera);
  }
}
