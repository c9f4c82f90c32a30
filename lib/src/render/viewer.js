// The orthoray viewer (docs/render.md, "Interactive viewer"). It draws the
// data the library embedded in the page (id "viewer-data"): the scene's
// elements, rays and targets, and the path's or the branches' segments in
// the order they were travelled. Pictures are not decisions: the numbers
// called "at" are floats in the picture's frame, used only to place shapes;
// the exact coordinates are the strings called "exact", shown as written.
"use strict";
(function () {
  const data = JSON.parse(document.getElementById("viewer-data").textContent);
  const svgNamespace = "http://www.w3.org/2000/svg";
  const scale = 600; // pixels per frame unit; the frame's longest side is 1
  const margin = 24;
  const dim = data.dim;
  const extent = data.extent;

  // The shading of docs/render.md: amber early, vermilion, deep purple late.
  const ramp = [[240, 163, 10], [214, 64, 40], [92, 24, 120]];
  function rampColour(fraction) {
    const f = Math.min(Math.max(fraction, 0), 1) * 2;
    const i = f >= 1 ? 1 : 0;
    const t = f - i;
    const c = [0, 1, 2].map((k) => Math.round(ramp[i][k] + t * (ramp[i + 1][k] - ramp[i][k])));
    return "rgb(" + c.join(",") + ")";
  }

  // 3D: an orthographic view, turned by yaw about z and then by pitch
  // about the screen's horizontal axis (a 3x3 rotation), z up at first.
  const initialTurn = { yaw: -0.5, pitch: -1.15 };
  const turn = { yaw: initialTurn.yaw, pitch: initialTurn.pitch };
  const centre = [0, 1, 2].map((j) => (j < dim ? extent[j] / 2 : 0));
  function rotation() {
    const cy = Math.cos(turn.yaw), sy = Math.sin(turn.yaw);
    const cp = Math.cos(turn.pitch), sp = Math.sin(turn.pitch);
    // Rx(pitch) * Rz(yaw)
    return [
      [cy, -sy, 0],
      [cp * sy, cp * cy, -sp],
      [sp * sy, sp * cy, cp],
    ];
  }
  let matrix = rotation();
  function project(p) {
    if (dim === 2) return [p[0] * scale, (extent[1] - p[1]) * scale];
    const d = [p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]];
    const x = matrix[0][0] * d[0] + matrix[0][1] * d[1] + matrix[0][2] * d[2];
    const y = matrix[1][0] * d[0] + matrix[1][1] * d[1] + matrix[1][2] * d[2];
    return [x * scale, -y * scale];
  }

  function make(name, attributes, parent) {
    const node = document.createElementNS(svgNamespace, name);
    for (const key in attributes) node.setAttribute(key, attributes[key]);
    if (parent) parent.appendChild(node);
    return node;
  }

  const stage = document.getElementById("stage");
  const svg = make("svg", { id: "picture", width: "100%", height: "100%" }, stage);
  const layers = {};
  for (const name of ["frame", "grid", "segments", "elements", "points", "markers"])
    layers[name] = make("g", { id: name }, svg);
  // Branches cover much of the picture: the elements go on top of them
  // (as in the SVG picture); a single path is drawn over the elements.
  if (data.mode === "path") svg.insertBefore(layers.elements, layers.segments);

  // Every drawn shape with the function that places it, so that a 3D
  // rotation only moves shapes.
  const placers = [];
  function placeLine(node, a, b) {
    const p = project(a), q = project(b);
    node.setAttribute("x1", p[0]);
    node.setAttribute("y1", p[1]);
    node.setAttribute("x2", q[0]);
    node.setAttribute("y2", q[1]);
  }
  function line(layer, a, b, attributes) {
    const node = make("line", attributes, layer);
    placers.push(() => placeLine(node, a, b));
    return node;
  }
  function dot(layer, at, radius, attributes) {
    const node = make("circle", attributes, layer);
    node.dataset.radius = radius;
    placers.push(() => {
      const p = project(at);
      node.setAttribute("cx", p[0]);
      node.setAttribute("cy", p[1]);
    });
    return node;
  }
  function polygon(layer, corners, attributes) {
    const node = make("polygon", attributes, layer);
    placers.push(() =>
      node.setAttribute("points", corners.map((c) => project(c).join(",")).join(" "))
    );
    return node;
  }
  function point3(p) {
    return [p[0], p[1], dim === 3 ? p[2] : 0];
  }

  // The frame: a rectangle in 2D (a puzzle's grid stands for it), a box
  // with its axes named in 3D.
  const box = [0, 1, 2].map((j) => (j < dim ? extent[j] : 0));
  if (dim === 2 && data.grid.length === 0) {
    const c = [[0, 0], [box[0], 0], [box[0], box[1]], [0, box[1]]];
    polygon(layers.frame, c, { class: "frame" });
  } else if (dim === 3) {
    for (let j = 0; j < 3; ++j)
      for (let corner = 0; corner < 4; ++corner) {
        const a = [0, 0, 0];
        const others = [0, 1, 2].filter((k) => k !== j);
        if (corner & 1) a[others[0]] = box[others[0]];
        if (corner & 2) a[others[1]] = box[others[1]];
        const b = a.slice();
        b[j] = box[j];
        line(layers.frame, a, b, { class: corner ? "frame" : "frame axis" });
      }
    ["x", "y", "z"].forEach((name, j) => {
      const at = [0, 0, 0];
      at[j] = box[j] * 1.06;
      const node = make("text", { class: "axis-name" }, layers.frame);
      node.textContent = name;
      placers.push(() => {
        const p = project(at);
        node.setAttribute("x", p[0]);
        node.setAttribute("y", p[1]);
      });
    });
  }

  for (const [a, b] of data.grid) line(layers.grid, point3(a), point3(b), { class: "grid" });

  // Elements: a segment in 2D (axis-aligned or diagonal), a rectangle in 3D.
  for (const e of data.elements) {
    const a = point3(e.a), b = point3(e.b);
    const attributes = {
      class: "element " + e.kind + (e.one_sided ? " one-sided" : ""),
      "data-exact": e.exact,
    };
    if (dim === 2) {
      line(layers.elements, a, b, attributes);
      continue;
    }
    const [p, q] = [0, 1, 2].filter((k) => k !== e.axis);
    const corners = [0, 1, 3, 2].map((corner) => {
      const c = a.slice();
      c[p] = corner & 1 ? b[p] : a[p];
      c[q] = corner & 2 ? b[q] : a[q];
      return c;
    });
    polygon(layers.elements, corners, attributes);
  }

  // Segments, in order; points where they end, shown with their segment.
  const segments = data.segments;
  const most = segments.reduce((m, s) => Math.max(m, s[2]), 0);
  const segmentNodes = segments.map((s, i) => {
    const fraction =
      data.mode === "path" ? i / Math.max(segments.length - 1, 1) : s[2] / Math.max(most, 1);
    return line(layers.segments, point3(data.points[s[0]].at), point3(data.points[s[1]].at), {
      class: "segment" + (s[3] === "e" ? " escape" : ""),
      stroke: rampColour(fraction),
      "data-index": i,
    });
  });
  const firstShown = data.points.map(() => Infinity);
  segments.forEach((s, i) => {
    firstShown[s[0]] = Math.min(firstShown[s[0]], i);
    firstShown[s[1]] = Math.min(firstShown[s[1]], i);
  });
  const pointNodes = [];
  const pointRadius = data.points.length > 200 ? 1.8 : 3; // a dense mesh stays readable
  data.points.forEach((p, i) => {
    if (!p.exact || firstShown[i] === Infinity) return;
    const node = dot(layers.points, point3(p.at), pointRadius, { class: "point", "data-exact": "point " + p.exact });
    pointNodes.push([node, firstShown[i]]);
  });
  const absorbedNodes = [];
  segments.forEach((s, i) => {
    if (s[3] !== "a") return;
    const node = dot(layers.points, point3(data.points[s[1]].at), 4, {
      class: "absorbed",
      "data-exact": "absorbed at " + data.points[s[1]].exact,
    });
    absorbedNodes.push([node, i]);
  });

  // Starts with an arrow along the direction, and targets by status.
  data.rays.forEach((ray, r) => {
    const at = point3(ray.at), d = point3(ray.direction);
    const ahead = at.map((x, j) => x + 0.05 * d[j]);
    line(layers.markers, at, ahead, { class: "start-arrow" });
    dot(layers.markers, at, 5, { class: "start", "data-exact": "ray " + (r + 1) + ": " + ray.exact });
  });
  data.targets.forEach((t, i) => {
    dot(layers.markers, point3(t.at), 7, {
      class: "target " + t.status,
      "data-exact": "target " + (i + 1) + (t.status === "plain" ? "" : " (" + t.status + ")") + ": " + t.exact,
    });
  });
  const head = dot(layers.markers, point3(data.rays[0].at), 5, { id: "head" });
  let headAt = point3(data.rays[0].at);
  placers.push(() => {
    const p = project(headAt);
    head.setAttribute("cx", p[0]);
    head.setAttribute("cy", p[1]);
  });

  // Zoom and pan by the viewBox; markers keep their size on the screen.
  let home;
  const view = {};
  function fit() {
    if (dim === 2) {
      // The frame, and a puzzle's grid where it reaches beyond the frame.
      const xs = [0, extent[0]], ys = [0, extent[1]];
      for (const ends of data.grid)
        for (const p of ends) {
          xs.push(p[0]);
          ys.push(p[1]);
        }
      const [left, top] = project([Math.min(...xs), Math.max(...ys)]);
      const [right, bottom] = project([Math.max(...xs), Math.min(...ys)]);
      home = [left - margin, top - margin, right - left + 2 * margin, bottom - top + 2 * margin];
    } else {
      const r = Math.hypot(extent[0], extent[1], extent[2]) * 0.55 * scale;
      home = [-r - margin, -r - margin, 2 * (r + margin), 2 * (r + margin)];
    }
  }
  function applyView() {
    svg.setAttribute("viewBox", [view.x, view.y, view.w, view.h].join(" "));
    const k = view.w / home[2];
    for (const node of svg.querySelectorAll("circle"))
      node.setAttribute("r", node.dataset.radius * k * 1.2);
  }
  function resetView() {
    turn.yaw = initialTurn.yaw;
    turn.pitch = initialTurn.pitch;
    matrix = rotation();
    placers.forEach((place) => place());
    [view.x, view.y, view.w, view.h] = home;
    applyView();
  }
  function userUnitsPerPixel() {
    const box = svg.getBoundingClientRect();
    return Math.max(view.w / box.width, view.h / box.height);
  }
  svg.addEventListener("wheel", (event) => {
    event.preventDefault();
    const factor = Math.exp(event.deltaY * 0.0015);
    const at = new DOMPoint(event.clientX, event.clientY).matrixTransform(svg.getScreenCTM().inverse());
    view.x = at.x - (at.x - view.x) * factor;
    view.y = at.y - (at.y - view.y) * factor;
    view.w *= factor;
    view.h *= factor;
    applyView();
  });
  let drag = null;
  svg.addEventListener("pointerdown", (event) => {
    drag = { x: event.clientX, y: event.clientY, rotate: dim === 3 && !event.shiftKey };
    svg.setPointerCapture(event.pointerId);
  });
  svg.addEventListener("pointermove", (event) => {
    if (!drag) return;
    const dx = event.clientX - drag.x, dy = event.clientY - drag.y;
    drag.x = event.clientX;
    drag.y = event.clientY;
    if (drag.rotate) {
      turn.yaw += dx * 0.01;
      turn.pitch += dy * 0.01;
      matrix = rotation();
      placers.forEach((place) => place());
    } else {
      const k = userUnitsPerPixel();
      view.x -= dx * k;
      view.y -= dy * k;
      applyView();
    }
  });
  svg.addEventListener("pointerup", () => (drag = null));

  // Hover: the exact coordinates of what is under the pointer.
  const readout = document.getElementById("readout");
  svg.addEventListener("mouseover", (event) => {
    const exact = event.target.getAttribute && event.target.getAttribute("data-exact");
    if (exact) readout.textContent = exact;
  });

  // The step slider: segments 0 .. k-1 are shown, the head at the end of
  // the last one shown.
  const slider = document.getElementById("step");
  const label = document.getElementById("step-label");
  slider.max = segments.length;
  slider.value = segments.length;
  function show(k) {
    segmentNodes.forEach((node, i) => node.classList.toggle("hidden", i >= k));
    for (const [node, first] of pointNodes) node.classList.toggle("hidden", first >= k);
    for (const [node, index] of absorbedNodes) node.classList.toggle("hidden", index >= k);
    headAt = k > 0 ? point3(data.points[segments[k - 1][1]].at) : point3(data.rays[0].at);
    const p = project(headAt);
    head.setAttribute("cx", p[0]);
    head.setAttribute("cy", p[1]);
    let text = "step " + k + " of " + segments.length;
    if (k > 0) text += ", reflections so far " + segments[k - 1][2];
    if (data.segments_received > segments.length)
      text += " (the first " + segments.length + " of " + data.segments_received + " segments are kept)";
    label.textContent = text;
  }
  slider.addEventListener("input", () => show(Number(slider.value)));

  const play = document.getElementById("play");
  let timer = null;
  function stop() {
    clearInterval(timer);
    timer = null;
    play.textContent = "play";
  }
  play.addEventListener("click", () => {
    if (timer) return stop();
    if (Number(slider.value) >= segments.length) slider.value = 0;
    const stride = Math.max(1, Math.round(segments.length / 300));
    play.textContent = "pause";
    timer = setInterval(() => {
      const k = Math.min(Number(slider.value) + stride, segments.length);
      slider.value = k;
      show(k);
      if (k >= segments.length) stop();
    }, 30);
  });
  document.getElementById("reset-view").addEventListener("click", resetView);

  // The texts: the answer, the caption, and how to use the view.
  document.getElementById("answer").textContent = data.answer || "answer not given";
  const caption = document.getElementById("caption");
  for (const text of data.caption) {
    if (text === data.answer) continue; // shown above, in bold
    const node = document.createElement("div");
    node.textContent = text;
    caption.appendChild(node);
  }
  if (data.elements.length < data.elements_total) {
    const node = document.createElement("div");
    node.textContent = "elements: the first " + data.elements.length + " of " + data.elements_total + " are drawn";
    caption.appendChild(node);
  }
  document.getElementById("help").textContent =
    "wheel: zoom; drag: " + (dim === 3 ? "rotate (shift-drag: pan)" : "pan") + "; slider: segments shown";

  fit();
  resetView();
  show(segments.length);
  document.body.dataset.ready = "true";
})();
