// splinekit — one localized drag of a Catmull-Rom control point (Eyiyurekli & Breen §3.3, §3.4).
//
// begin() fixes everything a drag needs: the active window, each window point's arc-length
// distance u = d / W to the dragged point (W the window's extent on its side), its drop-off weight
// S(u), and the curve normals at the window's two ends. move() then places every window point
// from the positions at begin(), so a drag is stable (the same displacement gives the same curve
// however it was reached) and allocation-free:
//   normals off:  P_i = P_i⁰ + S(u_i) D
//   normals on:   P_i = P_i⁰ + |D| S(u_i) slerp(D̂, N̂_side, u_i)
// where D is the dragged point's displacement and N_side the normal at that side's window end,
// turned to D's side of the curve. The dragged point moves by exactly D; the window's ends and
// every point outside the window keep their coordinates bit for bit.
#pragma once

#include <string>
#include <vector>

#include "edit/active_window.h"
#include "edit/catmull_rom.h"
#include "edit/falloff.h"

namespace splinekit::edit {

struct EditOptions {
  int left = 5;            // mL: control points on the left of the dragged one (the paper's examples use 5)
  int right = 5;           // nR: control points on the right
  FalloffOptions falloff;  // S: cosine, α = 1 unless set
  bool normals = false;    // §3.4: interpolate the direction towards the window ends' normals
};

class LocalEdit {
 public:
  // ---- Mutators -------------------------------------------------------------------------------
  // Starts a drag of control point `center` of `curve` (read now, not kept). Returns "" or a
  // message naming the problem (index out of range, negative side, α or σ not positive).
  std::string begin(const CatmullRom& curve, int center, const EditOptions& options);
  // Places the window's points for displacement (dx, dy) of the dragged point; no allocation.
  void move(double dx, double dy);
  // Ends the drag: points() keeps the last result.
  void end() { active_ = false; }

  // ---- Queries --------------------------------------------------------------------------------
  bool active() const { return active_; }
  const ActiveWindow& window() const { return window_; }
  const EditOptions& options() const { return options_; }
  // All control points after the last move(): 2·count doubles.
  const std::vector<double>& points() const { return points_; }
  // Per window slot k in [0, window().size()): control point index, u = d / W, weight S(u).
  const std::vector<int>& indices() const { return index_; }
  const std::vector<double>& distances() const { return u_; }
  const std::vector<double>& weights() const { return weight_; }
  // Unit curve normals at the left and right window ends (as at begin(), before orientation).
  Vec2 left_normal() const { return normal_[0]; }
  Vec2 right_normal() const { return normal_[1]; }

 private:
  bool active_ = false;
  ActiveWindow window_;
  EditOptions options_;
  std::vector<double> base_, points_;
  std::vector<int> index_;
  std::vector<double> u_, weight_;
  Vec2 normal_[2] = {Vec2(0, 1), Vec2(0, 1)};
};

}  // namespace splinekit::edit
