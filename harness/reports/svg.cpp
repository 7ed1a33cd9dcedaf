#include "harness/reports/svg.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace gm::harness {

std::string xml_escape(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  for (unsigned char c : s) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      case '\'':
        out += "&apos;";
        break;
      default:
        if (c < 0x20 && c != '\n' && c != '\t')
          out += ' ';  // not allowed in XML 1.0
        else
          out += static_cast<char>(c);
    }
  }
  return out;
}

namespace {

constexpr double W = 720, H = 460;
constexpr double L = 90, R = 230, T = 50, B = 70;  // margins; the legend lives in the right one
const char* kColours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};

std::string num(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", x);
  return buf;
}

std::string tick_label(double v, bool log) {
  char buf[32];
  if (log) {
    const int e = static_cast<int>(std::lround(std::log10(v)));
    if (e == 0) return "1";
    std::snprintf(buf, sizeof buf, "1e%d", e);
  } else {
    std::snprintf(buf, sizeof buf, "%g", std::abs(v) < 1e-12 ? 0.0 : v);
  }
  return buf;
}

struct Axis {
  bool log = false;
  double lo = 0, hi = 1;  // in transformed units (log10 when log)
  double f(double v) const { return log ? std::log10(v) : v; }
  std::vector<double> ticks() const {  // in data units
    std::vector<double> t;
    if (log) {
      const int a = static_cast<int>(std::ceil(lo - 1e-9)), b = static_cast<int>(std::floor(hi + 1e-9));
      const int stride = std::max(1, (b - a) / 8 + ((b - a) % 8 ? 1 : 0));
      for (int e = a; e <= b; e += stride) t.push_back(std::pow(10.0, e));
    } else {
      const double span = hi - lo;
      const double raw = span / 6;
      const double mag = std::pow(10.0, std::floor(std::log10(raw)));
      double step = mag;
      for (double m : {1.0, 2.0, 5.0, 10.0})
        if (raw <= m * mag) {
          step = m * mag;
          break;
        }
      for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * span; v += step) t.push_back(v);
    }
    return t;
  }
};

void fit(Axis& a, double mn, double mx) {
  if (!(mn < mx)) {
    const double pad = a.log ? 1.0 : (mn == 0 ? 1.0 : std::abs(mn) * 0.1);
    mn -= pad;
    mx += pad;
  }
  if (a.log) {
    a.lo = std::floor(mn);
    a.hi = std::ceil(mx);
  } else {
    const double pad = (mx - mn) * 0.05;
    a.lo = mn - pad;
    a.hi = mx + pad;
  }
}

// The fitted axes and the plot area inside the margins, shared by the drawing steps.
struct Plot {
  Axis ax, ay;
  double pw = W - L - R, ph = H - T - B;
  bool drawable(double x, double y) const {
    return std::isfinite(x) && std::isfinite(y) && (!ax.log || x > 0) && (!ay.log || y > 0);
  }
  double px(double x) const { return L + (ax.f(x) - ax.lo) / (ax.hi - ax.lo) * pw; }
  double py(double y) const { return T + ph - (ay.f(y) - ay.lo) / (ay.hi - ay.lo) * ph; }
};

// Fits both axes to the drawable points of every series; counts the points drawn and left out.
void fit_axes(Plot& plot, const std::vector<Series>& series, long& left_out, long& drawn) {
  Axis &ax = plot.ax, &ay = plot.ay;
  double xmn = HUGE_VAL, xmx = -HUGE_VAL, ymn = HUGE_VAL, ymx = -HUGE_VAL;
  for (const auto& s : series)
    for (const auto& [x, y] : s.points) {
      if (!plot.drawable(x, y)) {
        ++left_out;
        continue;
      }
      ++drawn;
      xmn = std::min(xmn, ax.f(x));
      xmx = std::max(xmx, ax.f(x));
      ymn = std::min(ymn, ay.f(y));
      ymx = std::max(ymx, ay.f(y));
    }
  if (drawn == 0) {
    xmn = ymn = ax.log ? 0 : 0;
    xmx = ymx = 1;
  }
  fit(ax, xmn, xmx);
  fit(ay, ymn, ymx);
}

// The svg header, the title, the grid with its ticks, the plot frame and the axis labels.
void draw_axes(std::ostringstream& o, const Plot& plot, const std::string& title, const std::string& x_label,
               const std::string& y_label) {
  const Axis &ax = plot.ax, &ay = plot.ay;
  const double pw = plot.pw, ph = plot.ph;
  o << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W
    << " " << H << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  o << "<rect x=\"0\" y=\"0\" width=\"" << W << "\" height=\"" << H << "\" fill=\"white\"/>\n";
  o << "<text x=\"" << num(W / 2) << "\" y=\"24\" text-anchor=\"middle\" font-size=\"15\">" << xml_escape(title)
    << "</text>\n";
  // Grid and ticks.
  for (double v : ax.ticks()) {
    const double x = plot.px(v);
    o << "<line x1=\"" << num(x) << "\" y1=\"" << T << "\" x2=\"" << num(x) << "\" y2=\"" << T + ph
      << "\" stroke=\"#e5e5e5\"/>\n";
    o << "<text x=\"" << num(x) << "\" y=\"" << num(T + ph + 18) << "\" text-anchor=\"middle\">"
      << xml_escape(tick_label(v, ax.log)) << "</text>\n";
  }
  for (double v : ay.ticks()) {
    const double y = plot.py(v);
    o << "<line x1=\"" << L << "\" y1=\"" << num(y) << "\" x2=\"" << L + pw << "\" y2=\"" << num(y)
      << "\" stroke=\"#e5e5e5\"/>\n";
    o << "<text x=\"" << num(L - 6) << "\" y=\"" << num(y + 4) << "\" text-anchor=\"end\">"
      << xml_escape(tick_label(v, ay.log)) << "</text>\n";
  }
  o << "<rect x=\"" << L << "\" y=\"" << T << "\" width=\"" << pw << "\" height=\"" << ph
    << "\" fill=\"none\" stroke=\"black\"/>\n";
  o << "<text x=\"" << num(L + pw / 2) << "\" y=\"" << num(H - 22) << "\" text-anchor=\"middle\">"
    << xml_escape(x_label) << (ax.log ? " (log scale)" : "") << "</text>\n";
  o << "<text transform=\"translate(18," << num(T + ph / 2) << ") rotate(-90)\" text-anchor=\"middle\">"
    << xml_escape(y_label) << (ay.log ? " (log scale)" : "") << "</text>\n";
}

// The dashed reference slope of a series on log-log axes, clipped to the plot; whether it was drawn.
bool draw_reference_slope(std::ostringstream& o, const Plot& plot, const Series& s, const char* colour) {
  const Axis &ax = plot.ax, &ay = plot.ay;
  const double pw = plot.pw, ph = plot.ph;
  bool slope_drawn = false;
  if (s.reference_slope != 0 && ax.log && ay.log) {
    // Through the first drawable point: log y = log y0 + p (log x - log x0).
    for (const auto& [x0, y0] : s.points) {
      if (!plot.drawable(x0, y0)) continue;
      const double lx0 = std::log10(x0), ly0 = std::log10(y0), p = s.reference_slope;
      double xa = ax.lo, xb = ax.hi;  // the part of the line inside the plot, in log10 units
      double ya = 0;
      const double x_at_lo = lx0 + (ay.lo - ly0) / p, x_at_hi = lx0 + (ay.hi - ly0) / p;
      xa = std::max(xa, std::min(x_at_lo, x_at_hi));
      xb = std::min(xb, std::max(x_at_lo, x_at_hi));
      if (!(xa < xb)) break;
      ya = ly0 + p * (xa - lx0);
      const double yb = ly0 + p * (xb - lx0);
      auto pxl = [&](double lx) { return L + (lx - ax.lo) / (ax.hi - ax.lo) * pw; };
      auto pyl = [&](double ly) { return T + ph - (ly - ay.lo) / (ay.hi - ay.lo) * ph; };
      o << "<line x1=\"" << num(pxl(xa)) << "\" y1=\"" << num(pyl(ya)) << "\" x2=\"" << num(pxl(xb)) << "\" y2=\""
        << num(pyl(yb)) << "\" stroke=\"" << colour << "\" stroke-dasharray=\"6,4\" stroke-width=\"1\"/>\n";
      slope_drawn = true;
      break;
    }
  }
  return slope_drawn;
}

// One series: its line, its points when few, its reference slope and its legend entries (from legend_y on).
void draw_series(std::ostringstream& o, const Plot& plot, const Series& s, const char* colour, double& legend_y) {
  std::vector<std::pair<double, double>> pts;
  for (const auto& [x, y] : s.points)
    if (plot.drawable(x, y)) pts.emplace_back(plot.px(x), plot.py(y));
  // No clipPath (not every renderer honours it): the axes are fitted to the data, and the one
  // line that could leave the plot, the reference slope, is clipped here.
  if (pts.size() > 1) {
    o << "<polyline fill=\"none\" stroke=\"" << colour << "\" stroke-width=\"1.6\" points=\"";
    for (const auto& [x, y] : pts) o << num(x) << "," << num(y) << " ";
    o << "\"/>\n";
  }
  if (pts.size() <= 60)
    for (const auto& [x, y] : pts)
      o << "<circle cx=\"" << num(x) << "\" cy=\"" << num(y) << "\" r=\"3\" fill=\"" << colour << "\"/>\n";
  const bool slope_drawn = draw_reference_slope(o, plot, s, colour);
  o << "<line x1=\"" << num(W - R + 12) << "\" y1=\"" << num(legend_y) << "\" x2=\"" << num(W - R + 36) << "\" y2=\""
    << num(legend_y) << "\" stroke=\"" << colour << "\" stroke-width=\"2\"/>\n";
  o << "<text x=\"" << num(W - R + 42) << "\" y=\"" << num(legend_y + 4) << "\">" << xml_escape(s.name) << "</text>\n";
  legend_y += 18;
  if (slope_drawn) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "slope %g (claimed)", s.reference_slope);
    o << "<line x1=\"" << num(W - R + 12) << "\" y1=\"" << num(legend_y) << "\" x2=\"" << num(W - R + 36) << "\" y2=\""
      << num(legend_y) << "\" stroke=\"" << colour << "\" stroke-dasharray=\"6,4\"/>\n";
    o << "<text x=\"" << num(W - R + 42) << "\" y=\"" << num(legend_y + 4) << "\">" << buf << "</text>\n";
    legend_y += 18;
  }
}

}  // namespace

std::string svg_plot(const std::string& title, const std::vector<Series>& series) {
  Plot plot;
  std::string x_label, y_label;
  for (const auto& s : series) {
    plot.ax.log = plot.ax.log || s.log_x;
    plot.ay.log = plot.ay.log || s.log_y;
    if (x_label.empty()) x_label = s.x_label;
    if (y_label.empty()) y_label = s.y_label;
  }
  long left_out = 0, drawn = 0;
  fit_axes(plot, series, left_out, drawn);
  const double pw = plot.pw, ph = plot.ph;

  std::ostringstream o;
  draw_axes(o, plot, title, x_label, y_label);

  // Series, reference slopes, legend.
  double legend_y = T + 6;
  int ci = 0;
  for (const auto& s : series) {
    const char* colour = kColours[ci++ % (sizeof kColours / sizeof kColours[0])];
    draw_series(o, plot, s, colour, legend_y);
  }
  if (drawn == 0)
    o << "<text x=\"" << num(L + pw / 2) << "\" y=\"" << num(T + ph / 2) << "\" text-anchor=\"middle\">"
      << "no drawable points</text>\n";
  if (left_out > 0)
    o << "<text x=\"" << L << "\" y=\"" << num(H - 6) << "\" font-size=\"11\" fill=\"#555\">" << left_out
      << " point(s) not drawn (zero, negative on a log axis, or not finite)</text>\n";
  o << "</svg>\n";
  return o.str();
}

}  // namespace gm::harness
