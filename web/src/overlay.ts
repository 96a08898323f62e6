// The 2D layer over the scene: the fixation the server used, the foveal region around it (the
// priority split in degrees of visual angle, through the display geometry) and the mouse.
import type { Display, Fixation } from "./gen/foveal/v1/foveal_pb";
import { FixationSource } from "./gen/foveal/v1/foveal_pb";

/**
 * Radius of a region of `deg` degrees of visual angle around the screen centre, as fractions of
 * the screen width and height (an ellipse when pixels are square but the screen is not).
 */
export function fovealRadius(display: Display, deg: number): { rx: number; ry: number } {
  const w = display.widthPx, h = display.heightPx;
  const pitchCm = (display.diagonalIn * 2.54) / Math.hypot(w, h);
  const px = (display.viewingDistanceCm * Math.tan((deg * Math.PI) / 180)) / pitchCm;
  return { rx: px / w, ry: px / h };
}

export class Overlay {
  private ctx: CanvasRenderingContext2D;
  constructor(readonly canvas: HTMLCanvasElement) {
    const ctx = canvas.getContext("2d");
    if (!ctx) throw new Error("no 2D canvas context");
    this.ctx = ctx;
  }

  resize(width: number, height: number): void {
    this.canvas.width = width;
    this.canvas.height = height;
  }

  /**
   * Lines of text at the top left, in place of the fixation (a close-up is not the server's view),
   * and marks at points given as fractions of the canvas: one point ringed, two joined.
   */
  label(lines: string[], marks: { x: number; y: number }[] = []): void {
    const { ctx, canvas } = this;
    ctx.clearRect(0, 0, canvas.width, canvas.height);
    ctx.font = "15px system-ui, sans-serif";
    ctx.textBaseline = "top";
    const width = Math.max(...lines.map((l) => ctx.measureText(l).width));
    ctx.fillStyle = "rgba(16,20,24,0.75)";
    ctx.fillRect(6, 6, width + 16, 22 * lines.length + 8);
    ctx.fillStyle = "rgba(255,214,10,0.95)";
    lines.forEach((l, i) => ctx.fillText(l, 14, 12 + 22 * i));
    ctx.strokeStyle = "rgba(255,214,10,0.95)";
    ctx.lineWidth = 2;
    ctx.beginPath();
    const w = canvas.width, h = canvas.height;
    if (marks.length === 1) ctx.arc(marks[0].x * w, marks[0].y * h, 12, 0, 2 * Math.PI);
    marks.forEach((m, i) => (i ? ctx.lineTo(m.x * w, m.y * h) : ctx.moveTo(m.x * w, m.y * h)));
    ctx.stroke();
  }

  draw(fix: Fixation | undefined, region: { rx: number; ry: number } | null, mouse: { x: number; y: number } | null): void {
    const { ctx, canvas } = this;
    const w = canvas.width, h = canvas.height;
    ctx.clearRect(0, 0, w, h);
    if (fix) {
      const x = fix.x * w, y = fix.y * h;
      const fallback = fix.source !== FixationSource.GAZE;
      ctx.strokeStyle = fallback ? "rgba(255,255,255,0.45)" : "rgba(255,214,10,0.95)";
      ctx.lineWidth = 2;
      if (region) {
        ctx.setLineDash(fallback ? [6, 6] : []);
        ctx.beginPath();
        ctx.ellipse(x, y, region.rx * w, region.ry * h, 0, 0, 2 * Math.PI);
        ctx.stroke();
        ctx.setLineDash([]);
      }
      ctx.beginPath();
      ctx.moveTo(x - 10, y);
      ctx.lineTo(x + 10, y);
      ctx.moveTo(x, y - 10);
      ctx.lineTo(x, y + 10);
      ctx.stroke();
    }
    if (mouse) {
      ctx.fillStyle = "rgba(120,200,255,0.9)";
      ctx.beginPath();
      ctx.arc(mouse.x * w, mouse.y * h, 3, 0, 2 * Math.PI);
      ctx.fill();
    }
  }
}
