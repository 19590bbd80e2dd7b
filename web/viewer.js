// The buildings in 3D: one instanced mesh per label, z up as grammars are
// (turned to three.js's y up at the root), picked by a click.
import * as THREE from 'three';
import { OrbitControls } from '/vendor/OrbitControls.js';

const GAP = 3;  // metres between buildings side by side
const HIGHLIGHT = new THREE.Color(1.0, 0.78, 0.1);

export class Viewer {
  constructor(element, onPick) {
    this.element = element;
    this.onPick = onPick;
    this.renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
    this.renderer.setPixelRatio(window.devicePixelRatio);
    this.renderer.setClearColor(0xf4f6f8);
    element.appendChild(this.renderer.domElement);
    this.scene = new THREE.Scene();
    // Sky and ground light, and a sun over the front left: roofs brightest,
    // fronts lighter than sides, so a box reads as a box.
    this.scene.add(new THREE.HemisphereLight(0xffffff, 0x707068, 0.9));
    const sun = new THREE.DirectionalLight(0xffffff, 2.4);
    sun.position.set(-0.5, 1.0, 0.7);
    this.scene.add(sun);
    this.root = new THREE.Group();
    this.root.rotation.x = -Math.PI / 2;  // grammar z up -> three.js y up
    this.scene.add(this.root);
    this.camera = new THREE.PerspectiveCamera(40, 1, 0.1, 100000);
    this.camera.position.set(-20, 25, 40);
    this.controls = new OrbitControls(this.camera, this.renderer.domElement);
    this.controls.addEventListener('change', () => this.draw());
    this.framed = '';       // what the camera was last framed on
    this.meshes = [];       // instanced meshes, each with .parts (the parts it draws)
    this.geometries = {};   // label -> unit geometry
    this.selected = null;
    new ResizeObserver(() => this.resize()).observe(element);
    let down = null;
    this.renderer.domElement.addEventListener('pointerdown', (e) => { down = [e.clientX, e.clientY]; });
    this.renderer.domElement.addEventListener('pointerup', (e) => {
      // A click, not the end of a drag that turned the view.
      if (down && Math.hypot(e.clientX - down[0], e.clientY - down[1]) < 4) this.pick(e.clientX, e.clientY, e);
    });
    this.resize();
  }

  resize() {
    const w = this.element.clientWidth || 1, h = this.element.clientHeight || 1;
    this.renderer.setSize(w, h, false);
    this.camera.aspect = w / h;
    this.camera.updateProjectionMatrix();
    this.draw();
  }

  draw() { this.renderer.render(this.scene, this.camera); }

  geometry(label, mesh) {
    const key = label + ':' + mesh.positions.length + ':' + mesh.indices.length;
    if (!this.geometries[key]) {
      const g = new THREE.BufferGeometry();
      g.setAttribute('position', new THREE.Float32BufferAttribute(mesh.positions, 3));
      g.setIndex(mesh.indices);
      const flat = g.toNonIndexed();  // faces shaded flat, as buildings are
      flat.computeVertexNormals();
      this.geometries[key] = flat;
    }
    return this.geometries[key];
  }

  clear() {
    for (const m of this.meshes) {
      this.root.remove(m);
      m.material.dispose();
      m.dispose();
    }
    this.meshes = [];
    this.selected = null;
  }

  // answer: derive_request's JSON; examples: the session's, or none.
  show(answer, examples) {
    this.clear();
    const byLabel = new Map();  // label index -> [{building, part, matrix}]
    let x = 0, depth = 0, height = 0;
    answer.buildings.forEach((b, bi) => {
      const offset = new THREE.Matrix4().makeTranslation(x, 0, 0);
      b.parts.forEach((p, pi) => {
        const m = new THREE.Matrix4().fromArray(p.matrix).premultiply(offset);
        if (!byLabel.has(p.label)) byLabel.set(p.label, []);
        byLabel.get(p.label).push({ building: bi, part: pi, matrix: m, colour: p.colour });
      });
      x += b.size[0] + GAP;
      depth = Math.max(depth, b.size[1]);
      height = Math.max(height, b.size[2]);
    });
    let width = Math.max(x - GAP, 1);
    for (const [label, parts] of byLabel) {
      const name = answer.labels[label];
      const material = new THREE.MeshLambertMaterial({ color: 0xffffff, side: THREE.DoubleSide });
      const mesh = new THREE.InstancedMesh(this.geometry(name, answer.meshes[name]), material, parts.length);
      const c = answer.colours[name];
      parts.forEach((p, i) => {
        mesh.setMatrixAt(i, p.matrix);
        mesh.setColorAt(i, p.colour ? new THREE.Color(...p.colour) : new THREE.Color(c[0], c[1], c[2]));
      });
      mesh.parts = parts;
      mesh.base = parts.map((p) => (p.colour ? new THREE.Color(...p.colour) : new THREE.Color(c[0], c[1], c[2])));
      this.root.add(mesh);
      this.meshes.push(mesh);
    }
    // The examples, boxes in their labels' colours, in a row behind.
    if (examples && examples.list.length) {
      let ex = 0;
      const y = depth + 4 * GAP;
      for (const e of examples.list) {
        let w = 0;
        const byName = new Map();
        for (const p of e.parts) {
          if (!byName.has(p.label)) byName.set(p.label, []);
          byName.get(p.label).push(p);
          w = Math.max(w, p.max[0]);
        }
        const minX = Math.min(...e.parts.map((p) => p.min[0]));
        for (const [name, parts] of byName) {
          const c = examples.colours[name] || [0.7, 0.7, 0.7];
          const mesh = new THREE.InstancedMesh(new THREE.BoxGeometry(1, 1, 1).translate(0.5, 0.5, 0.5),
                                               new THREE.MeshLambertMaterial({ color: new THREE.Color(c[0], c[1], c[2]) }), parts.length);
          parts.forEach((p, i) => {
            const s = [p.max[0] - p.min[0], p.max[1] - p.min[1], p.max[2] - p.min[2]];
            mesh.setMatrixAt(i, new THREE.Matrix4().makeScale(Math.max(s[0], 1e-3), Math.max(s[1], 1e-3), Math.max(s[2], 1e-3))
              .premultiply(new THREE.Matrix4().makeTranslation(ex + p.min[0] - minX, y + p.min[1], p.min[2])));
          });
          mesh.example = e.name;
          this.root.add(mesh);
          this.meshes.push(mesh);
        }
        ex += (w - minX) + GAP;
        height = Math.max(height, ...e.parts.map((p) => p.max[2]));
        depth = Math.max(depth, y + Math.max(...e.parts.map((p) => p.max[1])));
      }
      width = Math.max(width, ex - GAP);
    }
    const frame = answer.buildings.length + ':' + (examples ? examples.list.length : 0);
    if (frame !== this.framed) {
      this.framed = frame;
      const centre = new THREE.Vector3(width / 2, height / 2, -depth / 2);  // in y-up coordinates
      const reach = Math.max(width, height, depth) * 1.2 + 5;
      this.controls.target.copy(centre);
      this.camera.position.set(centre.x - reach * 0.35, centre.y + reach * 0.45, centre.z + reach * 1.1);
      this.controls.update();
    }
    this.draw();
  }

  // The part under (clientX, clientY), lit, or none.
  pick(clientX, clientY, event) {
    const r = this.renderer.domElement.getBoundingClientRect();
    const ndc = new THREE.Vector2(((clientX - r.left) / r.width) * 2 - 1, -((clientY - r.top) / r.height) * 2 + 1);
    const ray = new THREE.Raycaster();
    ray.setFromCamera(ndc, this.camera);
    const hit = ray.intersectObjects(this.meshes.filter((m) => m.parts), false)[0];
    if (!(event && event.shiftKey)) this.select(hit ? { mesh: hit.object, index: hit.instanceId } : null);
    this.onPick(hit ? hit.object.parts[hit.instanceId] : null, event);
  }

  select(target) {
    if (this.selected) {
      this.selected.mesh.setColorAt(this.selected.index, this.selected.mesh.base[this.selected.index]);
      this.selected.mesh.instanceColor.needsUpdate = true;
    }
    this.selected = target;
    if (target) {
      target.mesh.setColorAt(target.index, HIGHLIGHT);
      target.mesh.instanceColor.needsUpdate = true;
    }
    this.draw();
  }

  // Where on the page the middle of the first part whose test(entry) holds
  // is drawn ({x, y}, client pixels), or null: for tests and tours.
  whereIs(test) {
    for (const m of this.meshes) {
      if (!m.parts) continue;
      const i = m.parts.findIndex(test);
      if (i < 0) continue;
      const p = new THREE.Vector3(0.5, 0.5, 0.5).applyMatrix4(m.parts[i].matrix).applyMatrix4(this.root.matrixWorld).project(this.camera);
      const r = this.renderer.domElement.getBoundingClientRect();
      return { x: r.left + (p.x + 1) / 2 * r.width, y: r.top + (1 - p.y) / 2 * r.height };
    }
    return null;
  }

  // Every part whose test(part) holds, lit (a rule's text selects what it
  // made, a shift-click every part of a label); how many.
  lightWhere(test) {
    let lit = 0;
    for (const m of this.meshes) {
      if (!m.parts) continue;
      m.parts.forEach((p, i) => {
        const on = test(p);
        lit += on ? 1 : 0;
        m.setColorAt(i, on ? HIGHLIGHT : m.base[i]);
      });
      m.instanceColor.needsUpdate = true;
    }
    this.selected = null;
    this.draw();
    return lit;
  }
}
