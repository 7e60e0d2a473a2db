// The replay's timeline under the field: the whole log's sim time across the strip, a marker
// for each goal, penalty, fall and game-state change (the hello's `timeline`, made by the
// server's timeline.py), and the playhead. A click jumps to the marker under it (within
// SNAP_PX), or else to the time under it.
import { BADGES, TEAM_COLOURS } from "./draw.js";

export const SNAP_PX = 5;
// Marker kinds: where in the strip's height they sit (fractions) and their colour; a goal
// takes the scoring team's colour.
export const MARKERS = {
  state: { top: 0, bottom: 1, colour: "#9aa4ad", width: 1 },
  goal: { top: 0, bottom: 1, colour: null, width: 4 },
  penalty: { top: 0.08, bottom: 0.5, colour: BADGES.penalised.colour, width: 2 },
  fall: { top: 0.55, bottom: 0.92, colour: BADGES.fallen.colour, width: 2 },
};
const PAD_PX = 6; // the strip's ends are this far in, so markers at t0 and t1 show whole
const PLAYHEAD = "#ffffff";

export function markerColour(m) {
  return m.kind === "goal" ? TEAM_COLOURS[m.team] || "#ffffff" : MARKERS[m.kind].colour;
}

// Times outside the log (a marker before its first frame) sit at its ends.
export function timeToX(t, span, width) {
  const [t0, t1] = span, f = t1 > t0 ? (t - t0) / (t1 - t0) : 0;
  return PAD_PX + Math.min(Math.max(f, 0), 1) * (width - 2 * PAD_PX);
}

export function xToTime(x, span, width) {
  const [t0, t1] = span, f = (x - PAD_PX) / Math.max(1, width - 2 * PAD_PX);
  return t0 + Math.min(Math.max(f, 0), 1) * (t1 - t0);
}

// Draws the strip; returns each marker with the x (CSS px) it was drawn at, and the playhead's.
export function drawTimeline(ctx, width, height, span, markers, now) {
  ctx.fillStyle = "#0b0d10";
  ctx.fillRect(0, 0, width, height);
  ctx.fillStyle = "#252b33";
  ctx.fillRect(PAD_PX, height / 2 - 1, width - 2 * PAD_PX, 2);
  const order = ["state", "fall", "penalty", "goal"]; // goals on top
  // Whole pixels: a marker is crisp, never two half-tinted columns.
  const drawn = markers.map((m) => ({ ...m, x: Math.round(timeToX(m.t, span, width)) }));
  for (const kind of order) {
    const style = MARKERS[kind];
    for (const m of drawn) {
      if (m.kind !== kind) continue;
      ctx.fillStyle = markerColour(m);
      ctx.fillRect(m.x - Math.floor(style.width / 2), style.top * height, style.width, (style.bottom - style.top) * height);
    }
  }
  const playhead = now === null ? null : Math.round(timeToX(now, span, width) * 10) / 10;
  if (playhead !== null) {
    ctx.fillStyle = PLAYHEAD;
    ctx.beginPath();
    ctx.moveTo(playhead - 5, 0);
    ctx.lineTo(playhead + 5, 0);
    ctx.lineTo(playhead, 6);
    ctx.closePath();
    ctx.fill();
    ctx.fillRect(playhead - 0.5, 0, 1, height);
  }
  return { markers: drawn, playhead_x: playhead };
}

// The marker a click at x picks (goals first, then the nearest), or null.
export function markerAt(drawn, x) {
  const near = drawn.filter((m) => Math.abs(m.x - x) <= SNAP_PX);
  if (!near.length) return null;
  const rank = (m) => (m.kind === "goal" ? 0 : 1) * 1000 + Math.abs(m.x - x);
  return near.reduce((best, m) => (rank(m) < rank(best) ? m : best));
}
