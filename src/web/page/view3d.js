// The 3-D view of a motion (three.js, from Debian's libjs-three): the body drawn as its shape,
// turning as wobble's own samples say (the server's exact solution or its simulation; never
// integrated here), interpolated between samples by quaternion slerp. Physics frames: space z
// up; the body drawn in the frame its file is written in, the turning point at the origin.
// Arrows: e3 (red, fixed in the body), w (green) and the direction of L (blue) in space; the
// body cone rolling on the space cone for a torque-free symmetric top; the trace of the axle on
// a sphere under gravity; w(t) in the body, over |w(0)|, in a small plot below.
'use strict';

const VIEW_COLORS = {e3: 0xff0000, w: 0x1a9c3a, L: 0x2255dd, body: 0x8aa4c8, mark: 0x24324a};
const PLOT_COLORS = ['#b5462f', '#1a9c3a', '#2255dd'];
// At speed x1 the shown span plays in this many seconds of the wall clock.
const PLAY_SECONDS = 12;

function motionView(motion) {
  const root = el('div', {class: 'motion'});
  const canvas = el('canvas', {class: 'view3d', 'aria-label': '3-D view of the motion'});
  root.append(canvas);
  let renderer;
  try {
    renderer = new THREE.WebGLRenderer({canvas, antialias: true, preserveDrawingBuffer: true});
  } catch (e) {
    root.replaceChildren(el('p', {class: 'unit'}, 'The 3-D view needs WebGL, which this browser does not offer.'));
    return {element: root, destroy() {}};
  }
  const T = motion.t[motion.t.length - 1];
  const dt = T / (motion.t.length - 1);
  const quats = motion.q_BtoS.map(q => new THREE.Quaternion(q[1], q[2], q[3], q[0]));
  const scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf4f6fa);
  scene.add(new THREE.AmbientLight(0xffffff, 0.55));
  const sun = new THREE.DirectionalLight(0xffffff, 0.7);
  sun.position.set(3, -2, 5);
  scene.add(sun);

  // The body, scaled so that it fits in a sphere of radius 1, in a frame that turns with it.
  const bodyFrame = new THREE.Group();
  scene.add(bodyFrame);
  // Lengths divided here rather than by a scale on the group: a body of 1e19 m (the Earth's
  // box) would take the lighting's normals below float precision.
  const extent = Math.max(1e-300, ...motion.parts.map(partExtent));
  for (const part of motion.parts) {
    const scaled = Object.assign({}, part, {center: part.center.map(x => x / extent),
                                            sizes: (part.sizes || []).map(x => x / extent)});
    bodyFrame.add(partMesh(scaled, motion.turning_point === 'pivot'));
  }

  const arrow = (color, length) => new THREE.ArrowHelper(new THREE.Vector3(0, 0, 1),
    new THREE.Vector3(0, 0, 0), length, color, 0.18 * length, 0.09 * length);
  const e3 = arrow(VIEW_COLORS.e3, 1.5);
  bodyFrame.add(e3);
  const wArrow = arrow(VIEW_COLORS.w, 1.3), LArrow = arrow(VIEW_COLORS.L, 1.2);
  scene.add(wArrow, LArrow);
  addSpaceAxes(scene);
  if (motion.cones) addCones(scene, bodyFrame, motion.cones, 1.3);
  const trace = motion.gravity ? addTrace(scene, quats, 1.5) : null;

  const camera = new THREE.PerspectiveCamera(38, 1, 0.01, 100);
  camera.up.set(0, 0, 1);
  camera.position.set(2.5, -3.2, 1.9);
  const controls = new THREE.OrbitControls(camera, canvas);
  controls.enableDamping = false;

  // The controls: play/pause, speed, time slider, the time.
  const playButton = el('button', {type: 'button', class: 'play'}, 'Pause');
  const speed = el('select', {'aria-label': 'speed'},
    ...[0.25, 0.5, 1, 2, 4].map(s => el('option', {value: String(s)}, '×' + s)));
  speed.value = '1';
  const slider = el('input', {type: 'range', min: '0', max: '1000', value: '0', 'aria-label': 'time'});
  const clock = el('span', {class: 'clock'});
  root.append(el('div', {class: 'controls'}, playButton, speed, slider, clock));
  const plot = el('canvas', {class: 'wplot', 'aria-label': 'w(t) in the body'});
  root.append(plot);
  root.append(el('p', {class: 'legend'},
    legendItem('#ff0000', 'e₃'), legendItem('#1a9c3a', 'ω'), legendItem('#2255dd', 'L (direction)'),
    motion.cones ? 'cones: the body cone (fixed in the body) rolls on the space cone. ' : '',
    trace ? 'the trace of the axle on a sphere. ' : '',
    motion.parts.some(p => p.equivalent) ? 'The body is drawn as the box with its moments of inertia. ' : '',
    'Plot: ω₁, ω₂, ω₃ in the body over |ω(0)|. ' + methodWords(motion)));

  let t = 0, playing = true, last = null, rendered = 0, running = true;
  const q = new THREE.Quaternion();
  const wB = new THREE.Vector3(), L = new THREE.Vector3();

  function sampleAt(time) {
    const x = Math.min(Math.max(time / dt, 0), quats.length - 1);
    const i = Math.min(Math.floor(x), quats.length - 2), f = x - i;
    THREE.Quaternion.slerp(quats[i], quats[i + 1], q, f);
    const lerp = (a, b) => a.map((v, k) => v + f * (b[k] - v));
    wB.fromArray(lerp(motion.w_B[i], motion.w_B[i + 1]));
    L.fromArray(lerp(motion.L_dir_S[i], motion.L_dir_S[i + 1]));
    return i;
  }

  function draw() {
    const i = sampleAt(t);
    bodyFrame.quaternion.copy(q);
    const wS = wB.clone().applyQuaternion(q);
    const wLength = wS.length();
    if (wLength > 0) {
      wArrow.setDirection(wS.divideScalar(wLength));
      wArrow.setLength(1.3 * wLength, 0.18 * 1.3 * Math.min(wLength, 1), 0.09 * 1.3 * Math.min(wLength, 1));
    }
    wArrow.visible = wLength > 0;
    LArrow.visible = L.lengthSq() > 0;
    if (LArrow.visible) LArrow.setDirection(L.clone().normalize());
    if (trace) trace.geometry.setDrawRange(0, i + 2);
    resize();
    renderer.render(scene, camera);
    drawPlot(plot, motion, t, T);
    slider.value = String(Math.round(1000 * t / T));
    clock.textContent = 't = ' + t.toPrecision(4) + ' s of ' + T.toPrecision(4) + ' s';
    rendered += 1;
  }

  function resize() {
    const width = canvas.clientWidth, height = canvas.clientHeight;
    if (canvas.width !== Math.round(width * devicePixelRatio)) {
      renderer.setPixelRatio(devicePixelRatio);
      renderer.setSize(width, height, false);
      camera.aspect = width / height;
      camera.updateProjectionMatrix();
    }
  }

  function frame(now) {
    if (!running) return;
    if (playing && last !== null) {
      t += (now - last) / 1000 * Number(speed.value) * T / PLAY_SECONDS;
      if (t > T) t %= T;
    }
    last = now;
    draw();
    requestAnimationFrame(frame);
  }

  playButton.addEventListener('click', () => setPlaying(!playing));
  slider.addEventListener('input', () => {
    setPlaying(false);
    t = T * Number(slider.value) / 1000;
  });
  function setPlaying(on) {
    playing = on;
    playButton.textContent = on ? 'Pause' : 'Play';
  }
  requestAnimationFrame(frame);
  // For tests and for a lecturer's console: set the time, pause, count the frames drawn.
  window.wobbleView = {
    duration: T,
    setTime(time) { t = time; draw(); },
    pause() { setPlaying(false); },
    play() { setPlaying(true); },
    get rendered() { return rendered; },
  };
  return {element: root, destroy() { running = false; controls.dispose(); renderer.dispose(); }};
}

function legendItem(color, text) {
  return el('span', {class: 'key', style: 'color:' + color}, '▬ ' + text + '  ');
}

function methodWords(motion) {
  const words = {closed_form: 'the closed form', exact: 'the exact elliptic solution',
                 rkf78: 'Fehlberg 7(8)', dop853: 'Dormand-Prince 8(5,3)', vern9: 'Verner 9(8)',
                 dopri5: 'Dormand-Prince 5(4)', rk4: 'RK4',
                 split2: 'a splitting', split4: 'a splitting'};
  return 'Computed by ' + (words[motion.method] || motion.method) + '; shown with slerp between ' +
         motion.t.length + ' samples.';
}

// The radius of the sphere about the turning point that holds a part.
function partExtent(part) {
  const c = Math.hypot(...part.center);
  const s = part.sizes || [];
  switch (part.shape) {
    case 'box': return c + 0.5 * Math.hypot(...s);
    case 'plate': return c + 0.5 * Math.hypot(s[0], s[1]);
    case 'disc': case 'sphere': case 'shell': return c + s[0];
    case 'ring': return c + 1.05 * s[0];
    case 'cylinder': case 'cone': return c + Math.hypot(s[0], s[1]);
    case 'rod': return c + 0.5 * s[0];
    default: return c;  // a point
  }
}

// A part as three.js draws it, centred at its centre of mass, its axis along z; its lengths
// relative to the body's extent (1).
function partMesh(part, onPivot) {
  const group = new THREE.Group();
  const material = new THREE.MeshStandardMaterial({color: VIEW_COLORS.body, metalness: 0.1, roughness: 0.6});
  const mark = new THREE.MeshStandardMaterial({color: VIEW_COLORS.mark});
  const s = part.sizes || [];
  const alongZ = g => g.rotateX(Math.PI / 2);  // three's round shapes have their axis along y
  let mesh = null;
  switch (part.shape) {
    case 'box': mesh = new THREE.BoxBufferGeometry(s[0], s[1], s[2]); break;
    case 'plate': mesh = new THREE.BoxBufferGeometry(s[0], s[1], 0.02 * Math.max(s[0], s[1])); break;
    case 'disc': mesh = alongZ(new THREE.CylinderBufferGeometry(s[0], s[0], 0.06 * s[0], 48)); break;
    case 'cylinder': mesh = alongZ(new THREE.CylinderBufferGeometry(s[0], s[0], s[1], 48)); break;
    case 'sphere': mesh = new THREE.SphereBufferGeometry(s[0], 32, 16); break;
    case 'rod': mesh = alongZ(new THREE.CylinderBufferGeometry(0.02 * s[0], 0.02 * s[0], s[0], 12)); break;
    // The centre of mass of a cone is h/4 above its base; three's cone is centred at h/2.
    case 'cone': mesh = alongZ(new THREE.ConeBufferGeometry(s[0], s[1], 48).translate(0, -s[1] / 4, 0)); break;
    // A hoop lies in the x-y plane, as three's torus does; its tube is drawn a twentieth of R.
    case 'ring': mesh = new THREE.TorusBufferGeometry(s[0], 0.05 * s[0], 12, 64); break;
    // Hollow: seen through, so that it does not look like a solid ball.
    case 'shell':
      mesh = new THREE.SphereBufferGeometry(s[0], 32, 16);
      Object.assign(material, {transparent: true, opacity: 0.45});
      break;
    default: mesh = new THREE.SphereBufferGeometry(0.06, 16, 8);
  }
  group.add(new THREE.Mesh(mesh, material));
  if (['disc', 'cylinder', 'cone', 'sphere', 'ring', 'shell'].includes(part.shape)) {
    // A stripe along x, so that the spin about the axis shows.
    const r = s[0], h = part.shape === 'disc' ? 0.07 * r : 0.08 * r;
    const stripe = new THREE.Mesh(new THREE.BoxBufferGeometry(r, 0.08 * r, h), mark);
    stripe.position.set(r / 2, 0, part.shape === 'disc' ? 0 : (part.shape === 'cone' ? -s[1] / 4 : s[1] / 2 || 0));
    group.add(stripe);
  }
  group.quaternion.set(part.q[1], part.q[2], part.q[3], part.q[0]);
  group.position.fromArray(part.center);
  const holder = new THREE.Group();
  holder.add(group);
  const c = new THREE.Vector3().fromArray(part.center);
  if (onPivot && c.length() > 0) {
    // The light axle from the pivot to the part.
    const axle = new THREE.Mesh(new THREE.CylinderBufferGeometry(0.012, 0.012, c.length(), 8),
                                mark);
    axle.quaternion.setFromUnitVectors(new THREE.Vector3(0, 1, 0), c.clone().normalize());
    axle.position.copy(c.clone().multiplyScalar(0.5));
    holder.add(axle);
  }
  return holder;
}

function addSpaceAxes(scene) {
  const material = new THREE.LineBasicMaterial({color: 0x9aa3b0});
  for (const axis of [[1, 0, 0], [0, 1, 0], [0, 0, 1]]) {
    const g = new THREE.BufferGeometry().setFromPoints([new THREE.Vector3(0, 0, 0),
                                                        new THREE.Vector3(...axis).multiplyScalar(1.8)]);
    scene.add(new THREE.Line(g, material));
  }
}

// A cone with its apex at the origin, opening along `axis`, its slant `length`.
function coneMesh(axis, halfAngle, length, color) {
  const h = length * Math.cos(halfAngle), r = length * Math.sin(halfAngle);
  const g = new THREE.ConeBufferGeometry(r, h, 64, 1, true).translate(0, -h / 2, 0);
  const material = new THREE.MeshBasicMaterial({color, transparent: true, opacity: 0.22,
                                                side: THREE.DoubleSide, depthWrite: false});
  const mesh = new THREE.Mesh(g, material);
  mesh.quaternion.setFromUnitVectors(new THREE.Vector3(0, -1, 0), new THREE.Vector3(...axis).normalize());
  return mesh;
}

function addCones(scene, bodyFrame, cones, length) {
  scene.add(coneMesh(cones.space_axis_S, cones.space_half_angle, length, 0x2255dd));
  bodyFrame.add(coneMesh(cones.body_axis_B, cones.body_half_angle, length, 0xd08a2a));
}

// The path of the axle's tip (e3 at `radius`) over the whole run, drawn up to the present.
function addTrace(scene, quats, radius) {
  const points = quats.map(q => new THREE.Vector3(0, 0, radius).applyQuaternion(q));
  const line = new THREE.Line(new THREE.BufferGeometry().setFromPoints(points),
                              new THREE.LineBasicMaterial({color: 0x7a2a8a}));
  scene.add(line);
  const sphere = new THREE.Mesh(new THREE.SphereBufferGeometry(radius, 32, 16),
    new THREE.MeshBasicMaterial({color: 0x9aa3b0, wireframe: true, transparent: true, opacity: 0.12}));
  scene.add(sphere);
  return line;
}

// w in the body over |w(0)|, its three components against t, with the present marked. The
// curves are drawn once per size into a canvas of their own; each frame copies it and adds the
// present.
function drawPlot(plot, motion, t, T) {
  const width = plot.clientWidth, height = plot.clientHeight;
  const ratio = devicePixelRatio;
  if (!plot.curves || plot.width !== Math.round(width * ratio)) {
    plot.width = Math.round(width * ratio);
    plot.height = Math.round(height * ratio);
    plot.curves = document.createElement('canvas');
    plot.curves.width = plot.width;
    plot.curves.height = plot.height;
    drawCurves(plot.curves.getContext('2d'), motion, width, height, T, ratio);
  }
  const g = plot.getContext('2d');
  g.setTransform(1, 0, 0, 1, 0, 0);
  g.clearRect(0, 0, plot.width, plot.height);
  g.drawImage(plot.curves, 0, 0);
  g.setTransform(ratio, 0, 0, ratio, 0, 0);
  const x = 30 + (width - 40) * t / T;
  g.strokeStyle = '#333'; g.lineWidth = 1;
  g.beginPath(); g.moveTo(x, 4); g.lineTo(x, height - 4); g.stroke();
}

function drawCurves(g, motion, width, height, T, ratio) {
  g.setTransform(ratio, 0, 0, ratio, 0, 0);
  let top = 0;
  for (const w of motion.w_B) top = Math.max(top, Math.abs(w[0]), Math.abs(w[1]), Math.abs(w[2]));
  top = top || 1;
  const x = time => 30 + (width - 40) * time / T;
  const y = v => height / 2 - (height / 2 - 8) * v / top;
  g.strokeStyle = '#ccd'; g.lineWidth = 1;
  g.beginPath(); g.moveTo(30, y(0)); g.lineTo(width - 10, y(0)); g.stroke();
  g.fillStyle = '#667'; g.font = '11px system-ui, sans-serif';
  g.fillText(top.toPrecision(2), 2, y(top) + 4);
  g.fillText((-top).toPrecision(2), 2, y(-top));
  for (let c = 0; c < 3; ++c) {
    g.strokeStyle = PLOT_COLORS[c]; g.lineWidth = 1.5;
    g.beginPath();
    motion.w_B.forEach((w, k) => (k ? g.lineTo : g.moveTo).call(g, x(motion.t[k]), y(w[c])));
    g.stroke();
  }
  ['ω₁', 'ω₂', 'ω₃'].forEach((name, c) => {
    g.fillStyle = PLOT_COLORS[c];
    g.fillText(name, width - 90 + 28 * c, 12);
  });
}
