// The office map on a canvas: the occupancy image from /v1/map.png, anchors with labels, people
// at their places coloured by availability, the robot's pose and planned path, and AMCL's
// particle cloud. World metres become image pixels with the map metadata (resolution, origin):
//   px = (x - origin_x) / resolution,   py = height - (y - origin_y) / resolution
// since the PNG's top row is the map's last row.

import { authHeaders, scoped } from "./api.js";

const COLOURS = {
  robot: "#6a1b9a",
  path: "#0b5cad",
  particle: "rgba(217, 72, 15, 0.55)",
  anchor: "#30363d",
  label: "#1b1f24",
  available: "#1e7d3c",
  unavailable: "#b3261e",
  unknown: "#5f6b7a",
};

export class MapView {
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = canvas.getContext("2d");
    this.info = null;
    this.image = null;
    this.robot = null;
    this.others = []; // robots 2, 3.. of a fleet (GET /v1/robots), drawn like the first
    this.people = [];
    this.showParticles = true;
    this.showLabels = true;
    this.scale = 1; // canvas pixels per map cell
    this.unit = 1; // canvas pixels per CSS pixel: marks and labels keep their on-screen size
    // The canvas backing store follows its on-screen size, so labels stay sharp and legible.
    new ResizeObserver(() => this.resize()).observe(canvas.parentElement);
  }

  resize() {
    if (!this.info) return;
    const unit = window.devicePixelRatio || 1;
    const cssWidth = this.canvas.parentElement.clientWidth || this.info.width;
    const width = Math.round(cssWidth * unit);
    if (width === this.canvas.width && unit === this.unit) return;
    this.unit = unit;
    this.scale = width / this.info.width;
    this.canvas.width = width;
    this.canvas.height = Math.round(this.info.height * this.scale);
    this.draw();
  }

  async load() {
    const headers = authHeaders();
    const infoResponse = await fetch(scoped("/v1/map"), { headers });
    if (!infoResponse.ok) throw new Error(`map metadata: HTTP ${infoResponse.status}`);
    const info = await infoResponse.json();
    const imageResponse = await fetch(scoped(info.image), { headers });
    if (!imageResponse.ok) throw new Error(`map image: HTTP ${imageResponse.status}`);
    this.image = await createImageBitmap(await imageResponse.blob());
    this.info = info;
    this.canvas.width = 0; // force resize() to size the backing store
    this.resize();
    this.canvas.dataset.ready = "true";
  }

  /** World metres to canvas pixels. */
  toPixel(x, y) {
    const { resolution, origin, height } = this.info;
    return [((x - origin[0]) / resolution) * this.scale, (height - (y - origin[1]) / resolution) * this.scale];
  }

  setRobot(state) {
    this.robot = state;
    this.draw();
  }

  /** Every robot of the office, the first as setRobot shows it; each numbered when several. */
  setRobots(states) {
    this.robot = states[0] ?? null;
    this.others = states.slice(1);
    this.draw();
  }

  /** people: [{id, name, place, available: true|false|null}] */
  setPeople(people) {
    this.people = people;
    this.draw();
  }

  draw() {
    if (!this.info) return;
    const { ctx, canvas } = this;
    ctx.setTransform(1, 0, 0, 1, 0, 0);
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    ctx.imageSmoothingEnabled = false;
    ctx.drawImage(this.image, 0, 0, canvas.width, canvas.height);
    this.drawAnchors();
    this.drawPeople();
    if (this.showParticles) this.drawParticles();
    this.drawPath();
    this.drawRobot();
    this.drawOthers();
  }

  drawAnchors() {
    const { ctx, unit: u } = this;
    // Small canvases (a phone) get a smaller font; labels that would still overlap another
    // label or a person's disc try the other sides of their anchor, and are left out when no
    // side is free (the anchor's square stays), so no two labels ever overlap.
    const cssWidth = this.canvas.width / u;
    const size = cssWidth < 520 ? 9 : 11;
    ctx.font = `${size * u}px system-ui, sans-serif`;
    ctx.textBaseline = "middle";
    ctx.textAlign = "center";
    // Clear of the people's discs and the robot's marker (drawn over the labels), and a
    // little apart from each other, so two names never read as one ("Print roomCoffee corner").
    const taken = [...this.peopleDiscs(), ...this.robotDisc()];
    const drawn = [];
    const apart = 3 * u;
    for (const anchor of Object.values(this.info.anchors)) {
      const [px, py] = this.toPixel(anchor.x, anchor.y);
      ctx.fillStyle = COLOURS.anchor;
      ctx.fillRect(px - 2 * u, py - 2 * u, 4 * u, 4 * u);
      if (!this.showLabels) continue;
      const width = ctx.measureText(anchor.name).width + 4 * u;
      const height = (size + 3) * u;
      const gap = size * u;
      const spots = [[0, -gap], [0, gap], [width / 2 + 6 * u, 0], [-width / 2 - 6 * u, 0]];
      for (const [dx, dy] of spots) {
        const box = { x: px + dx - width / 2, y: py + dy - height / 2, w: width, h: height };
        const inside = box.x >= 0 && box.y >= 0 && box.x + box.w <= this.canvas.width && box.y + box.h <= this.canvas.height;
        const spaced = { x: box.x - apart, y: box.y, w: box.w + 2 * apart, h: box.h };
        if (!inside || taken.some((other) => overlaps(box, other)) || drawn.some((other) => overlaps(spaced, other))) continue;
        // A white halo keeps the label readable over walls.
        ctx.lineWidth = 3 * u;
        ctx.strokeStyle = "rgba(255, 255, 255, 0.9)";
        ctx.strokeText(anchor.name, px + dx, py + dy);
        ctx.fillStyle = COLOURS.label;
        ctx.fillText(anchor.name, px + dx, py + dy);
        drawn.push(box);
        break;
      }
    }
    ctx.textAlign = "start";
    // Where the labels went, in CSS pixels, for tests and for anyone checking the layout.
    this.canvas.dataset.labels = JSON.stringify(drawn.map((b) => [b.x, b.y, b.w, b.h].map((v) => +(v / u).toFixed(1))));
    this.canvas.dataset.marks = JSON.stringify(taken.map((b) => [b.x, b.y, b.w, b.h].map((v) => +(v / u).toFixed(1))));
  }

  /** The box the robot's marker covers (see drawRobot), nose included; none without a pose. */
  robotDisc() {
    const u = this.unit;
    return [this.robot, ...this.others]
      .filter((robot) => robot?.pose)
      .map((robot) => {
        const [px, py] = this.toPixel(robot.pose.x, robot.pose.y);
        return { x: px - 16 * u, y: py - 16 * u, w: 32 * u, h: 32 * u };
      });
  }

  /** The boxes the people's discs cover (see drawPeople), so labels keep clear of them. */
  peopleDiscs() {
    const u = this.unit;
    const boxes = [];
    for (const [px, py] of this.peoplePositions()) boxes.push({ x: px - 9 * u, y: py - 9 * u, w: 18 * u, h: 18 * u });
    return boxes;
  }

  /** [x, y, person] canvas positions: several people at one place sit side by side. */
  peoplePositions() {
    const u = this.unit;
    const atPlace = new Map();
    const out = [];
    for (const person of this.people) {
      const anchor = this.info.anchors[person.place];
      if (!anchor) continue;
      const n = atPlace.get(person.place) ?? 0;
      atPlace.set(person.place, n + 1);
      const [px, py] = this.toPixel(anchor.x, anchor.y);
      out.push([px + (n - 0.5) * 20 * u, py + 14 * u, person]);
    }
    return out;
  }

  drawPeople() {
    const { ctx, unit: u } = this;
    for (const [px, py, person] of this.peoplePositions()) {
      ctx.beginPath();
      ctx.arc(px, py, 9 * u, 0, 2 * Math.PI);
      ctx.fillStyle = person.available === true ? COLOURS.available
        : person.available === false ? COLOURS.unavailable : COLOURS.unknown;
      ctx.fill();
      ctx.fillStyle = "#ffffff";
      ctx.font = `bold ${9 * u}px system-ui, sans-serif`;
      ctx.textAlign = "center";
      ctx.fillText(initials(person.name || person.id), px, py + 0.5);
      ctx.textAlign = "start";
    }
  }

  drawParticles() {
    const particles = this.robot?.particles;
    if (!particles?.length) return;
    const { ctx, unit: u } = this;
    ctx.strokeStyle = COLOURS.particle;
    ctx.lineWidth = u;
    ctx.beginPath();
    for (const [x, y, yaw] of particles) {
      const [px, py] = this.toPixel(x, y);
      ctx.moveTo(px, py);
      ctx.lineTo(px + 6 * u * Math.cos(yaw), py - 6 * u * Math.sin(yaw));
    }
    ctx.stroke();
  }

  drawPath() {
    const path = this.robot?.path;
    this.canvas.dataset.path = String(path?.length ?? 0); // points drawn, for tests
    if (!path?.length) return;
    const { ctx, unit: u } = this;
    ctx.strokeStyle = COLOURS.path;
    ctx.lineWidth = 3 * u;
    ctx.setLineDash([8 * u, 5 * u]);
    ctx.beginPath();
    path.forEach(([x, y], i) => {
      const [px, py] = this.toPixel(x, y);
      if (i === 0) ctx.moveTo(px, py);
      else ctx.lineTo(px, py);
    });
    ctx.stroke();
    ctx.setLineDash([]);
  }

  drawRobot() {
    const pose = this.robot?.pose;
    if (!pose) return;
    const { ctx, unit: u } = this;
    const [px, py] = this.toPixel(pose.x, pose.y);
    const yaw = pose.yaw ?? 0;
    // A disc with a nose pointing along the heading (canvas y grows downwards: -sin).
    this.drawDisc(px, py);
    ctx.beginPath();
    ctx.moveTo(px, py);
    ctx.lineTo(px + 16 * u * Math.cos(yaw), py - 16 * u * Math.sin(yaw));
    ctx.strokeStyle = "#ffffff";
    ctx.lineWidth = 3 * u;
    ctx.stroke();
    // Where the marker is, in canvas pixels, for tests and assistive summaries.
    this.canvas.dataset.robot = `${px.toFixed(1)},${py.toFixed(1)}`;
    if (this.others.length) this.drawNumber(px, py, 1);
  }

  /** A robot's disc, white-rimmed, at canvas pixel (px, py). */
  drawDisc(px, py) {
    const { ctx, unit: u } = this;
    ctx.beginPath();
    ctx.arc(px, py, 11 * u, 0, 2 * Math.PI);
    ctx.fillStyle = COLOURS.robot;
    ctx.fill();
    ctx.strokeStyle = "#ffffff";
    ctx.lineWidth = 2 * u;
    ctx.stroke();
  }

  /** Robots 2, 3..: their planned paths and numbered markers. */
  drawOthers() {
    const { ctx, unit: u } = this;
    const where = this.robot?.pose ? [this.canvas.dataset.robot] : [];
    this.others.forEach((robot, i) => {
      if (!robot.pose) return;
      if (robot.path?.length) {
        ctx.strokeStyle = COLOURS.path;
        ctx.lineWidth = 2 * u;
        ctx.setLineDash([4 * u, 4 * u]);
        ctx.beginPath();
        robot.path.forEach(([x, y], k) => {
          const [px, py] = this.toPixel(x, y);
          if (k === 0) ctx.moveTo(px, py);
          else ctx.lineTo(px, py);
        });
        ctx.stroke();
        ctx.setLineDash([]);
      }
      const [px, py] = this.toPixel(robot.pose.x, robot.pose.y);
      this.drawDisc(px, py);
      this.drawNumber(px, py, i + 2);
      where.push(`${px.toFixed(1)},${py.toFixed(1)}`);
    });
    // Every robot's marker, "x,y;x,y", for tests and assistive summaries.
    this.canvas.dataset.robots = where.join(";");
  }

  drawNumber(px, py, n) {
    const { ctx, unit: u } = this;
    ctx.fillStyle = "#ffffff";
    ctx.font = `bold ${11 * u}px system-ui, sans-serif`;
    ctx.textAlign = "center";
    ctx.textBaseline = "middle";
    ctx.fillText(String(n), px, py + 0.5);
    ctx.textAlign = "start";
  }
}

function overlaps(a, b) {
  return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

function initials(name) {
  return name.split(/\s+/).filter(Boolean).slice(0, 2).map((w) => w[0].toUpperCase()).join("");
}
