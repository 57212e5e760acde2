// The office map on a canvas: the occupancy image from /v1/map.png, anchors with labels, people
// at their places coloured by availability, the robot's pose and planned path, and AMCL's
// particle cloud. World metres become image pixels with the map metadata (resolution, origin):
//   px = (x - origin_x) / resolution,   py = height - (y - origin_y) / resolution
// since the PNG's top row is the map's last row.

import { authHeaders } from "./api.js";

const SCALE = 1.6; // canvas pixels per map cell: room for legible labels
const COLOURS = {
  robot: "#6a1b9a",
  path: "#0b5cad",
  particle: "rgba(217, 72, 15, 0.55)",
  anchor: "#30363d",
  label: "#1b1f24",
  available: "#1e7d3c",
  unavailable: "#b3261e",
  unknown: "#8a94a3",
};

export class MapView {
  constructor(canvas) {
    this.canvas = canvas;
    this.ctx = canvas.getContext("2d");
    this.info = null;
    this.image = null;
    this.robot = null;
    this.people = [];
    this.showParticles = true;
    this.showLabels = true;
  }

  async load() {
    const headers = authHeaders();
    const infoResponse = await fetch("/v1/map", { headers });
    if (!infoResponse.ok) throw new Error(`map metadata: HTTP ${infoResponse.status}`);
    const info = await infoResponse.json();
    const imageResponse = await fetch(info.image, { headers });
    if (!imageResponse.ok) throw new Error(`map image: HTTP ${imageResponse.status}`);
    this.image = await createImageBitmap(await imageResponse.blob());
    this.info = info;
    this.canvas.width = Math.round(info.width * SCALE);
    this.canvas.height = Math.round(info.height * SCALE);
    this.canvas.dataset.ready = "true";
    this.draw();
  }

  /** World metres to canvas pixels. */
  toPixel(x, y) {
    const { resolution, origin, height } = this.info;
    return [((x - origin[0]) / resolution) * SCALE, (height - (y - origin[1]) / resolution) * SCALE];
  }

  setRobot(state) {
    this.robot = state;
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
  }

  drawAnchors() {
    const { ctx } = this;
    ctx.font = "11px system-ui, sans-serif";
    ctx.textBaseline = "middle";
    for (const anchor of Object.values(this.info.anchors)) {
      const [px, py] = this.toPixel(anchor.x, anchor.y);
      ctx.fillStyle = COLOURS.anchor;
      ctx.fillRect(px - 2, py - 2, 4, 4);
      if (this.showLabels) {
        ctx.fillStyle = COLOURS.label;
        ctx.fillText(anchor.name, px + 5, py - 8);
      }
    }
  }

  drawPeople() {
    const { ctx } = this;
    const atPlace = new Map();
    for (const person of this.people) {
      const anchor = this.info.anchors[person.place];
      if (!anchor) continue;
      const n = atPlace.get(person.place) ?? 0;
      atPlace.set(person.place, n + 1);
      let [px, py] = this.toPixel(anchor.x, anchor.y);
      // Several people at one place (a facility's guards) sit side by side.
      px += 14 + n * 20;
      py += 10;
      ctx.beginPath();
      ctx.arc(px, py, 8, 0, 2 * Math.PI);
      ctx.fillStyle = person.available === true ? COLOURS.available
        : person.available === false ? COLOURS.unavailable : COLOURS.unknown;
      ctx.fill();
      ctx.fillStyle = "#ffffff";
      ctx.font = "bold 9px system-ui, sans-serif";
      ctx.textAlign = "center";
      ctx.fillText(initials(person.name || person.id), px, py + 0.5);
      ctx.textAlign = "start";
    }
  }

  drawParticles() {
    const particles = this.robot?.particles;
    if (!particles?.length) return;
    const { ctx } = this;
    ctx.strokeStyle = COLOURS.particle;
    ctx.lineWidth = 1;
    ctx.beginPath();
    for (const [x, y, yaw] of particles) {
      const [px, py] = this.toPixel(x, y);
      ctx.moveTo(px, py);
      ctx.lineTo(px + 6 * Math.cos(yaw), py - 6 * Math.sin(yaw));
    }
    ctx.stroke();
  }

  drawPath() {
    const path = this.robot?.path;
    if (!path?.length) return;
    const { ctx } = this;
    ctx.strokeStyle = COLOURS.path;
    ctx.lineWidth = 3;
    ctx.setLineDash([8, 5]);
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
    const { ctx } = this;
    const [px, py] = this.toPixel(pose.x, pose.y);
    const yaw = pose.yaw ?? 0;
    // A disc with a nose pointing along the heading (canvas y grows downwards: -sin).
    ctx.beginPath();
    ctx.arc(px, py, 11, 0, 2 * Math.PI);
    ctx.fillStyle = COLOURS.robot;
    ctx.fill();
    ctx.strokeStyle = "#ffffff";
    ctx.lineWidth = 2;
    ctx.stroke();
    ctx.beginPath();
    ctx.moveTo(px, py);
    ctx.lineTo(px + 16 * Math.cos(yaw), py - 16 * Math.sin(yaw));
    ctx.strokeStyle = "#ffffff";
    ctx.lineWidth = 3;
    ctx.stroke();
    // Where the marker is, in canvas pixels, for tests and assistive summaries.
    this.canvas.dataset.robot = `${px.toFixed(1)},${py.toFixed(1)}`;
  }
}

function initials(name) {
  return name.split(/\s+/).filter(Boolean).slice(0, 2).map((w) => w[0].toUpperCase()).join("");
}
