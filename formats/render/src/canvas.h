// Anti-aliased 2-D drawing on an Image: strokes, fills, markers. Coverage is computed
// analytically (distance to the stroke, exact horizontal span overlap for fills), so the result
// is smooth without supersampling the whole picture.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "cablefit/formats/image.h"

namespace cablefit::render {

using Point2 = Eigen::Vector2d;  // [px], x right, y down

/// Dash pattern in pixels (on, off, on, off, ...); empty = solid.
using DashPattern = std::vector<double>;

/// Strokes a polyline of `width` px as one shape (joints are not blended twice). Non-finite
/// points break the line.
void StrokePolyline(Image& image, const std::vector<Point2>& points, double width, Rgb colour,
                    const DashPattern& dash = {}, double alpha = 1.0);
void StrokeSegment(Image& image, const Point2& a, const Point2& b, double width, Rgb colour,
                   double alpha = 1.0);
/// Fills a polygon (even-odd rule).
void FillPolygon(Image& image, const std::vector<Point2>& polygon, Rgb colour, double alpha = 1.0);
void FillRect(Image& image, double x0, double y0, double x1, double y1, Rgb colour,
              double alpha = 1.0);
void FillCircle(Image& image, const Point2& centre, double radius, Rgb colour, double alpha = 1.0);
void StrokeCircle(Image& image, const Point2& centre, double radius, double width, Rgb colour,
                  double alpha = 1.0);
/// An arrow from `tail` to `head` with a filled head of `head_size` px.
void DrawArrow(Image& image, const Point2& tail, const Point2& head, double width,
               double head_size, Rgb colour);

}  // namespace cablefit::render
