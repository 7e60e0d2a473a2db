// Drawing the field and one world_truth_t on a 2D canvas. Field frame: mm, origin at the
// centre, +x towards the goal team 0 attacks, +y left; screen y grows downwards. Every size
// (field, goals, ball, feet, camera, sonar) is the match's own, from its TL_MATCH (the
// hello's `match`): nothing here knows a config.

export const TEAM_COLOURS = ["#1e63ff", "#e8232a"]; // team 0 blue, team 1 red
export const INACTIVE_COLOUR = "#8c8c8c";
export const PENALISED_COLOURS = ["#5577c5", "#ba575b"]; // the team colours half way to grey
// Badges by a robot's number: P while penalised (on the bench), F while fallen.
export const BADGES = { penalised: { text: "P", colour: "#ffd21f" }, fallen: { text: "F", colour: "#ff4fd8" } };
export const BALL_COLOUR = "#ff7f00";
const CARPET = "#2e7d32";
const LINE = "#f4f4f4";

// The thesis camera model (Algorithm 2.3, sim/src/camera.cpp): a cone of field_of_view_rad
// along body heading + head yaw whose range grows as the head looks up (pitch is + down):
// near_range + range_span * (max_pitch - pitch) / (max_pitch - min_pitch), pitch clamped.
export function cameraRangeMm(camera, pitch) {
  const { min_pitch_rad: lo, max_pitch_rad: hi } = camera;
  const clamped = Math.min(Math.max(pitch, lo), hi);
  return camera.near_range_mm + camera.range_span_mm * (hi - clamped) / (hi - lo);
}

// The mm -> canvas-pixel transform that fits the field and its border into w x h CSS px.
export function makeView(field, w, h) {
  const spanX = field.length_mm + 2 * field.border_mm, spanY = field.width_mm + 2 * field.border_mm;
  const s = Math.min(w / spanX, h / spanY);
  const ox = w / 2, oy = h / 2;
  return { s, w, h, px: (x) => ox + x * s, py: (y) => oy - y * s };
}

const round1 = (v) => Math.round(v * 10) / 10;

export function drawField(ctx, v, f) {
  const L = f.length_mm / 2, W = f.width_mm / 2, B = f.border_mm, lw = f.line_width_mm;
  ctx.fillStyle = "#1b1f24";
  ctx.fillRect(0, 0, v.w, v.h);
  ctx.fillStyle = CARPET;
  ctx.fillRect(v.px(-L - B), v.py(W + B), (2 * L + 2 * B) * v.s, (2 * W + 2 * B) * v.s);
  ctx.strokeStyle = LINE;
  ctx.lineWidth = Math.max(1, lw * v.s);
  const inset = lw / 2; // lengths are to the lines' outer edges
  const rect = (x0, y0, x1, y1) => ctx.strokeRect(v.px(x0), v.py(y1), (x1 - x0) * v.s, (y1 - y0) * v.s);
  rect(-L + inset, -W + inset, L - inset, W - inset);
  line(ctx, v, 0, -W + inset, 0, W - inset);
  ctx.beginPath();
  ctx.arc(v.px(0), v.py(0), (f.centre_circle_diameter_mm / 2 - inset) * v.s, 0, 2 * Math.PI);
  ctx.stroke();
  for (const side of [-1, 1]) {
    boxAtGoal(rect, side, L, inset, f.goal_box_length_mm, f.goal_box_width_mm);
    boxAtGoal(rect, side, L, inset, f.penalty_area_length_mm, f.penalty_area_width_mm);
    cross(ctx, v, side * (L - f.penalty_mark_distance_mm), 0, 50);
    drawGoal(ctx, v, f, side);
  }
  cross(ctx, v, 0, 0, 50);
}

function boxAtGoal(rect, side, L, inset, depth, width) {
  if (depth <= 0 || width <= 0) return; // e.g. no penalty area on the 2011 field
  const xGoal = side * (L - inset), xIn = side * (L - depth + inset);
  rect(Math.min(xGoal, xIn), -width / 2 + inset, Math.max(xGoal, xIn), width / 2 - inset);
}

function line(ctx, v, x0, y0, x1, y1) {
  ctx.beginPath();
  ctx.moveTo(v.px(x0), v.py(y0));
  ctx.lineTo(v.px(x1), v.py(y1));
  ctx.stroke();
}

function cross(ctx, v, x, y, halfMm) {
  line(ctx, v, x - halfMm, y, x + halfMm, y);
  line(ctx, v, x, y - halfMm, x, y + halfMm);
}

function drawGoal(ctx, v, f, side) {
  const xLine = side * f.length_mm / 2, xBack = side * (f.length_mm / 2 + f.goal_depth_mm);
  const halfW = f.goal_width_mm / 2;
  ctx.save();
  ctx.fillStyle = "rgba(220, 220, 220, 0.25)";
  ctx.strokeStyle = "#d0d0d0";
  ctx.lineWidth = 1;
  const x0 = v.px(Math.min(xLine, xBack)), y0 = v.py(halfW);
  ctx.fillRect(x0, y0, f.goal_depth_mm * v.s, 2 * halfW * v.s);
  ctx.strokeRect(x0, y0, f.goal_depth_mm * v.s, 2 * halfW * v.s);
  ctx.fillStyle = "#fff8c0";
  ctx.strokeStyle = "#333";
  for (const y of [-halfW, halfW]) {
    ctx.beginPath();
    ctx.arc(v.px(side * (f.length_mm / 2 - f.line_width_mm / 2)), v.py(y),
      Math.max(2.5, f.goal_post_diameter_mm / 2 * v.s), 0, 2 * Math.PI);
    ctx.fill();
    ctx.stroke();
  }
  ctx.restore();
}

export function robotColour(r) {
  if (!r.active) return INACTIVE_COLOUR;
  return (r.penalised ? PENALISED_COLOURS : TEAM_COLOURS)[r.team] || INACTIVE_COLOUR;
}

function drawCameraCone(ctx, v, camera, r) {
  const [x, y, th] = r.body, [yaw, pitch] = r.head;
  const dir = th + yaw, half = camera.field_of_view_rad / 2, range = cameraRangeMm(camera, pitch) * v.s;
  ctx.save();
  ctx.beginPath();
  ctx.moveTo(v.px(x), v.py(y));
  ctx.arc(v.px(x), v.py(y), range, -(dir + half), -(dir - half)); // screen angles are mirrored
  ctx.closePath();
  ctx.globalAlpha = 0.09;
  ctx.fillStyle = robotColour(r);
  ctx.fill();
  ctx.globalAlpha = 0.4;
  ctx.lineWidth = 1;
  ctx.strokeStyle = robotColour(r);
  ctx.stroke();
  ctx.restore();
  return { dir_rad: Math.round(dir * 1000) / 1000, range_px: round1(range) };
}

function drawFoot(ctx, v, foot, pose, colour) {
  const [x, y, th] = pose, l = foot.length_mm * v.s, w = foot.width_mm * v.s;
  ctx.save();
  ctx.translate(v.px(x), v.py(y));
  ctx.rotate(-th);
  ctx.fillStyle = colour;
  ctx.fillRect(-l / 2, -w / 2, l, w);
  ctx.lineWidth = 1;
  ctx.strokeStyle = "rgba(0, 0, 0, 0.6)";
  ctx.strokeRect(-l / 2, -w / 2, l, w);
  ctx.restore();
}

function drawHeading(ctx, v, r) {
  const [x, y, th] = r.body, len = Math.max(14, 260 * v.s), head = Math.max(5, 70 * v.s);
  const x0 = v.px(x), y0 = v.py(y), x1 = x0 + len * Math.cos(th), y1 = y0 - len * Math.sin(th);
  ctx.save();
  ctx.strokeStyle = "#101010";
  ctx.fillStyle = "#101010";
  ctx.lineWidth = 2;
  ctx.beginPath();
  ctx.moveTo(x0, y0);
  ctx.lineTo(x1, y1);
  ctx.stroke();
  ctx.beginPath();
  ctx.moveTo(x1 + 2 * Math.cos(th), y1 - 2 * Math.sin(th));
  ctx.lineTo(x1 - head * Math.cos(th - 0.45), y1 + head * Math.sin(th - 0.45));
  ctx.lineTo(x1 - head * Math.cos(th + 0.45), y1 + head * Math.sin(th + 0.45));
  ctx.closePath();
  ctx.fill();
  ctx.restore();
}

// The chest LED the robot asked for (act_t, carried in the truth), as a disc on the body
// centre between the feet (a third of their separation, so both feet stay in view); off
// (black) draws nothing. Magenta (#ff00ff) is the shim's "behaviour failed".
function drawLed(ctx, v, foot, r) {
  if (!r.led || r.led === "#000000") return null;
  const radius = Math.max(3, foot.separation_mm / 3 * v.s);
  ctx.save();
  ctx.beginPath();
  ctx.arc(v.px(r.body[0]), v.py(r.body[1]), radius, 0, 2 * Math.PI);
  ctx.fillStyle = r.led;
  ctx.fill();
  ctx.lineWidth = 1;
  ctx.strokeStyle = "#000";
  ctx.stroke();
  ctx.restore();
  return { colour: r.led, radius_px: round1(radius) };
}

const labelY = (v, r) => v.py(r.body[1]) - Math.max(16, 170 * v.s);
const roleY = (v, r) => v.py(r.body[1]) + Math.max(16, 170 * v.s);

// A label on the field: white text with a black outline, readable on grass, lines and feet.
function drawOutlinedText(ctx, text, x, y, sizePx, fill) {
  ctx.save();
  ctx.font = `bold ${sizePx}px 'DejaVu Sans', sans-serif`;
  ctx.textAlign = "center";
  ctx.textBaseline = "middle";
  ctx.lineWidth = 3;
  ctx.strokeStyle = "#000";
  ctx.strokeText(text, x, y);
  ctx.fillStyle = fill;
  ctx.fillText(text, x, y);
  ctx.restore();
}

// The role the robot's behaviour plays (from its team message, see decode.py), under its feet.
function drawRole(ctx, v, r, role) {
  if (!role) return null;
  const x = v.px(r.body[0]), y = roleY(v, r);
  drawOutlinedText(ctx, role, x, y, 10, "#fff");
  return { text: role, px: round1(x), py: round1(y) };
}

function drawNumber(ctx, v, r) {
  drawOutlinedText(ctx, String(r.player), v.px(r.body[0]), labelY(v, r), 13, r.active ? "#fff" : "#c8c8c8");
}

// The sonar (thesis Algorithm 2.4) watches a corridor ahead of the robot, half_width_mm either
// side of its centre line and range_mm long; the left half gives sonar_left. A reading is the
// nearest obstacle as a fraction of the range (1: nothing). Each half with an obstacle is drawn
// as a bar from the body centre (under the feet) to the obstacle, with a cap across the half there.
export const SONAR_COLOUR = "#00e5ff";

function drawSonar(ctx, v, sonar, r, reading) {
  if (!reading) return null; // no TL_SENSE for this frame or robot
  const [x, y, th] = r.body, c = Math.cos(th), s = Math.sin(th), w = sonar.half_width_mm;
  const at = (ahead, left) => [x + ahead * c - left * s, y + ahead * s + left * c];
  const bars = [];
  ctx.save();
  ctx.fillStyle = ctx.strokeStyle = SONAR_COLOUR;
  ctx.lineWidth = 2;
  for (const [side, value, sign] of [["left", reading[0], 1], ["right", reading[1], -1]]) {
    if (!(value < 1)) continue;
    const len = Math.max(0, value) * sonar.range_mm;
    ctx.beginPath();
    for (const [a, l] of [[0, 0.2], [len, 0.2], [len, 0.8], [0, 0.8]]) {
      const [px, py] = at(a, sign * l * w);
      ctx.lineTo(v.px(px), v.py(py));
    }
    ctx.fill();
    line(ctx, v, ...at(len, 0), ...at(len, sign * w));
    bars.push({ side, length_mm: round1(len), end: pixel(v, at(len, sign * w / 2)) });
  }
  ctx.restore();
  return { left: reading[0], right: reading[1], bars };
}

function drawFallen(ctx, v, foot, r) { // a cross over the body
  const [x, y] = r.body, d = (foot.length_mm / 2 + 30) * v.s;
  ctx.save();
  ctx.strokeStyle = "#101010";
  ctx.lineWidth = 3;
  ctx.beginPath();
  ctx.moveTo(v.px(x) - d, v.py(y) - d);
  ctx.lineTo(v.px(x) + d, v.py(y) + d);
  ctx.moveTo(v.px(x) - d, v.py(y) + d);
  ctx.lineTo(v.px(x) + d, v.py(y) - d);
  ctx.stroke();
  ctx.restore();
}

function drawBadges(ctx, v, r) { // right of the number
  const radius = 8, y = labelY(v, r);
  return Object.keys(BADGES).filter((k) => r[k]).map((k, i) => {
    const { text, colour } = BADGES[k], x = v.px(r.body[0]) + 16 + i * (2 * radius + 3);
    ctx.save();
    ctx.beginPath();
    ctx.arc(x, y, radius, 0, 2 * Math.PI);
    ctx.fillStyle = colour;
    ctx.fill();
    ctx.lineWidth = 1;
    ctx.strokeStyle = "#000";
    ctx.stroke();
    ctx.font = "bold 11px 'DejaVu Sans', sans-serif";
    ctx.textAlign = "center";
    ctx.textBaseline = "middle";
    ctx.fillStyle = "#000";
    ctx.fillText(text, x, y + 0.5);
    ctx.restore();
    return { text, colour, px: round1(x), py: round1(y), radius_px: radius };
  });
}

// What each robot believes (its act_t): its pose as a dashed ring with a heading tick, the
// uncertainty ellipse of its position (BELIEF_SIGMAS standard deviations along the covariance's
// axes), a faint line from where it truly is, and the ball it believes as a dashed ring; all in
// a light tint of its team colour (BELIEF_COLOURS), apart from the truth's saturated feet. A
// ball it has not seen for a while fades; one it never saw is not drawn.
export const BELIEF_COLOURS = ["#8fb0ff", "#ff9a9d"];
export const BELIEF_SIGMAS = 2;
export const BELIEF_RING_MM = 120;
const NEVER_SEEN_FRAMES = 1 << 20;
const BALL_FADE_FRAMES = 90; // 3 s without seeing it: drawn at its faintest

// Semi-axes (mm, along the major then the minor axis) and the major axis's angle (rad, field
// frame) of the BELIEF_SIGMAS ellipse of a 2x2 covariance [xx, xy, yy] (mm^2).
export function covarianceEllipse(cov) {
  const [xx, xy, yy] = cov, mid = (xx + yy) / 2, diff = Math.hypot((xx - yy) / 2, xy);
  const major = Math.sqrt(Math.max(mid + diff, 0)), minor = Math.sqrt(Math.max(mid - diff, 0));
  return { major_mm: BELIEF_SIGMAS * major, minor_mm: BELIEF_SIGMAS * minor, angle_rad: 0.5 * Math.atan2(2 * xy, xx - yy) };
}

function drawBelief(ctx, v, match, b, truth) {
  const colour = BELIEF_COLOURS[b.team] || INACTIVE_COLOUR, out = { team: b.team, player: b.player, colour };
  ctx.save();
  ctx.strokeStyle = ctx.fillStyle = colour;
  ctx.lineWidth = 2;
  if (b.pose) {
    const [x, y, th] = b.pose, px = v.px(x), py = v.py(y), ring = Math.max(5, BELIEF_RING_MM * v.s);
    if (truth) {
      ctx.save();
      ctx.globalAlpha = 0.5;
      ctx.lineWidth = 1;
      ctx.setLineDash([2, 3]);
      line(ctx, v, truth.body[0], truth.body[1], x, y);
      ctx.restore();
    }
    if (b.cov) {
      const e = covarianceEllipse(b.cov);
      if (e.major_mm > 0) {
        ctx.save();
        ctx.beginPath();
        ctx.ellipse(px, py, Math.max(1, e.major_mm * v.s), Math.max(1, e.minor_mm * v.s), -e.angle_rad, 0, 2 * Math.PI);
        ctx.globalAlpha = 0.15;
        ctx.fill();
        ctx.globalAlpha = 0.8;
        ctx.lineWidth = 1.5;
        ctx.setLineDash([5, 4]);
        ctx.stroke();
        ctx.restore();
        out.ellipse = { major_px: round1(e.major_mm * v.s), minor_px: round1(e.minor_mm * v.s),
          angle_rad: Math.round(e.angle_rad * 1000) / 1000 };
      }
    }
    ctx.setLineDash([4, 3]);
    ctx.beginPath();
    ctx.arc(px, py, ring, 0, 2 * Math.PI);
    ctx.stroke();
    ctx.setLineDash([]);
    ctx.beginPath();
    ctx.moveTo(px, py);
    ctx.lineTo(px + 1.6 * ring * Math.cos(th), py - 1.6 * ring * Math.sin(th));
    ctx.stroke();
    out.pose = { ...pixel(v, b.pose), theta: th, ring_px: round1(ring) };
  }
  if (b.ball && b.ball_lost < NEVER_SEEN_FRAMES) {
    const radius = Math.max(4.5, match.ball_diameter_mm / 2 * v.s) + 1;
    const alpha = 1 - 0.65 * Math.min(Math.max(b.ball_lost, 0), BALL_FADE_FRAMES) / BALL_FADE_FRAMES;
    ctx.globalAlpha = alpha;
    ctx.setLineDash([3, 2]);
    ctx.beginPath();
    ctx.arc(v.px(b.ball[0]), v.py(b.ball[1]), radius, 0, 2 * Math.PI);
    ctx.stroke();
    out.ball = { ...pixel(v, b.ball), radius_px: round1(radius), alpha: Math.round(alpha * 100) / 100 };
  }
  ctx.restore();
  return out;
}

function drawBall(ctx, v, diameterMm, ball) {
  const r = Math.max(4.5, diameterMm / 2 * v.s);
  ctx.save();
  ctx.beginPath();
  ctx.arc(v.px(ball[0]), v.py(ball[1]), r, 0, 2 * Math.PI);
  ctx.fillStyle = BALL_COLOUR;
  ctx.fill();
  ctx.lineWidth = 1;
  ctx.strokeStyle = "#3a1d00";
  ctx.stroke();
  ctx.restore();
  return r;
}

function clipToCarpet(ctx, v, f) {
  const x = f.length_mm / 2 + f.border_mm, y = f.width_mm / 2 + f.border_mm;
  ctx.beginPath();
  ctx.rect(v.px(-x), v.py(y), 2 * x * v.s, 2 * y * v.s);
  ctx.clip();
}

const pixel = (v, pose) => ({ x: pose[0], y: pose[1], px: round1(v.px(pose[0])), py: round1(v.py(pose[1])) });

// Draws one truth frame over the field of `match` (the hello's), with the sonar of the same
// frame's sense (or null), each robot's role and, with showBeliefs, what it believes
// (`beliefs`, from its act); returns what it drew, in canvas pixels.
export function drawTruth(ctx, v, match, truth, sense, beliefs = [], showBeliefs = true) {
  const key = (r) => `${r.team}/${r.player}`;
  const sonars = new Map((sense ? sense.robots : []).map((s) => [key(s), s.sonar]));
  const believed = new Map((beliefs || []).map((b) => [key(b), b]));
  const truthOf = new Map(truth.robots.map((r) => [key(r), r]));
  ctx.save();
  clipToCarpet(ctx, v, match.field); // the boundary walls: no camera sees past them
  const robots = truth.robots.map((r) => ({ r, cone: drawCameraCone(ctx, v, match.camera, r) }));
  ctx.restore();
  for (const robot of robots) robot.sonar = drawSonar(ctx, v, match.sonar, robot.r, sonars.get(key(robot.r)));
  // Beliefs under the truth: the robots and the ball as they are stay whole on top.
  const drawnBeliefs = showBeliefs ? [...believed.values()].map((b) => drawBelief(ctx, v, match, b, truthOf.get(key(b)))) : [];
  for (const robot of robots) {
    const { r } = robot;
    drawFoot(ctx, v, match.foot, r.left, robotColour(r));
    drawFoot(ctx, v, match.foot, r.right, robotColour(r));
    drawHeading(ctx, v, r);
    robot.led = drawLed(ctx, v, match.foot, r);
    if (r.fallen) drawFallen(ctx, v, match.foot, r);
  }
  for (const robot of robots) {
    drawNumber(ctx, v, robot.r);
    robot.badges = drawBadges(ctx, v, robot.r);
    const belief = believed.get(key(robot.r));
    robot.role = drawRole(ctx, v, robot.r, belief ? belief.role : null);
  }
  const ballRadius = truth.ball ? drawBall(ctx, v, match.ball_diameter_mm, truth.ball) : 0;
  return {
    ball: truth.ball ? { ...pixel(v, truth.ball), radius_px: round1(ballRadius), colour: BALL_COLOUR } : null,
    robots: robots.map(({ r, cone, sonar, badges, led, role }) => ({
      team: r.team, player: r.player, active: r.active, penalised: r.penalised, fallen: r.fallen,
      colour: robotColour(r), body: { ...pixel(v, r.body), theta: r.body[2] },
      left: pixel(v, r.left), right: pixel(v, r.right), camera: cone, sonar, badges, led, role,
    })),
    beliefs: drawnBeliefs,
  };
}
