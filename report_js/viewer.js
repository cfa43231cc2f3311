// report.html's 3D view: each frame's fitted surfaces with its data points,
// from the JSON in <script id="pfdm-scene"> (report/report_scene.cc).
// Bundled with the parts of three.js it uses by esbuild at build time
// (CMakeLists.txt) and inlined into the page: no file beside it, no network.
import {
  AmbientLight, BufferAttribute, BufferGeometry, Color, DirectionalLight,
  DoubleSide, Mesh, MeshPhongMaterial, PerspectiveCamera, Points,
  PointsMaterial, Scene, Vector3, WebGLRenderer,
} from 'three';

function positions(ints, scale) {
  const out = new Float32Array(ints.length);
  for (let i = 0; i < ints.length; ++i) out[i] = ints[i] * scale;
  return out;
}

// The camera turns about the target: dragging turns it about the long axis
// (left-right) and across it (up-down), the wheel moves it nearer.
function orbit(canvas, camera, target, render) {
  let last = null;
  canvas.addEventListener('pointerdown', (e) => {
    last = [e.clientX, e.clientY];
    canvas.setPointerCapture(e.pointerId);
  });
  canvas.addEventListener('pointerup', () => { last = null; });
  canvas.addEventListener('pointermove', (e) => {
    if (!last) return;
    const offset = camera.position.clone().sub(target);
    offset.applyAxisAngle(camera.up, -(e.clientX - last[0]) * 0.01);
    const right = offset.clone().cross(camera.up).normalize();
    const turned = offset.clone().applyAxisAngle(right, (e.clientY - last[1]) * 0.01);
    if (Math.abs(turned.clone().normalize().dot(camera.up)) < 0.98) offset.copy(turned);
    camera.position.copy(target).add(offset);
    camera.lookAt(target);
    last = [e.clientX, e.clientY];
    render();
  });
  canvas.addEventListener('wheel', (e) => {
    e.preventDefault();
    const offset = camera.position.clone().sub(target);
    offset.multiplyScalar(Math.exp(Math.sign(e.deltaY) * 0.1));
    camera.position.copy(target).add(offset);
    render();
  }, {passive: false});
}

// The apex is a surface's first vertex, the base rim its last ring.
function frameAxes(surface, meridians, scale) {
  const n = surface.length / 3;
  const base = new Vector3();
  for (let i = n - meridians; i < n; ++i) {
    base.add(new Vector3(surface[3 * i], surface[3 * i + 1], surface[3 * i + 2]));
  }
  base.multiplyScalar(scale / meridians);
  const apex = new Vector3(surface[0], surface[1], surface[2]).multiplyScalar(scale);
  const length = base.distanceTo(apex);
  return {up: base.clone().sub(apex).normalize(), center: base.add(apex).multiplyScalar(0.5), length};
}

function start() {
  const root = document.getElementById('pfdm-view3d');
  const json = document.getElementById('pfdm-scene');
  if (!root || !json) return;
  const data = JSON.parse(json.textContent);
  const canvas = root.querySelector('canvas');
  const slider = root.querySelector('input[type=range]');
  const play = root.querySelector('button');
  const label = root.querySelector('.pfdm-frame');
  let renderer;
  try {
    renderer = new WebGLRenderer({canvas, antialias: true, preserveDrawingBuffer: true});
  } catch (error) {
    label.textContent = 'This browser gives no WebGL: ' + error.message;
    return;
  }
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setSize(canvas.clientWidth, canvas.clientHeight, false);
  const scene = new Scene();
  scene.background = new Color(0xffffff);
  scene.add(new AmbientLight(0xffffff, 1.2));
  const camera = new PerspectiveCamera(35, canvas.clientWidth / canvas.clientHeight, 1, 5000);
  const light = new DirectionalLight(0xffffff, 2.0);
  camera.add(light);
  scene.add(camera);
  const index = new BufferAttribute(new Uint32Array(data.triangles), 1);
  const walls = data.walls.map((wall) => {
    const geometry = new BufferGeometry();
    geometry.setIndex(index);
    const mesh = new Mesh(geometry, new MeshPhongMaterial({
      color: new Color(wall.color), side: DoubleSide, transparent: wall.opacity < 1,
      opacity: wall.opacity, depthWrite: wall.opacity >= 1, shininess: 20,
    }));
    scene.add(mesh);
    return mesh;
  });
  const points = new Points(new BufferGeometry(),
      new PointsMaterial({color: 0xc0392b, size: 2.0, sizeAttenuation: false}));
  scene.add(points);

  const axes = frameAxes(data.frames[0].surfaces[0], data.meridians, data.scale);
  camera.up.copy(axes.up);
  const side = new Vector3(1, 0, 0);
  if (Math.abs(side.dot(axes.up)) > 0.9) side.set(0, 1, 0);
  side.sub(axes.up.clone().multiplyScalar(side.dot(axes.up))).normalize();
  // From the side and a little above the base, so that the base's opening
  // shows the walls' two surfaces.
  camera.position.copy(axes.center).add(side.multiplyScalar(2.4 * axes.length))
      .add(axes.up.clone().multiplyScalar(0.8 * axes.length));
  camera.lookAt(axes.center);

  const render = () => {
    renderer.render(scene, camera);
    if (renderer.info.render.triangles > 0) canvas.dataset.drawn = '1';
  };
  const show = (t) => {
    const frame = data.frames[t];
    walls.forEach((mesh, k) => {
      mesh.geometry.setAttribute('position',
          new BufferAttribute(positions(frame.surfaces[k], data.scale), 3));
      mesh.geometry.computeVertexNormals();
    });
    points.geometry.setAttribute('position',
        new BufferAttribute(positions(frame.points, data.scale), 3));
    label.textContent = frame.label;
    slider.value = t;
    render();
  };
  slider.max = data.frames.length - 1;
  slider.addEventListener('input', () => show(Number(slider.value)));
  let timer = null;
  play.addEventListener('click', () => {
    if (timer) {
      clearInterval(timer);
      timer = null;
      play.textContent = 'Play';
      return;
    }
    play.textContent = 'Pause';
    timer = setInterval(() => show((Number(slider.value) + 1) % data.frames.length),
        data.frame_ms);
  });
  orbit(canvas, camera, axes.center, render);
  show(0);
}

start();
