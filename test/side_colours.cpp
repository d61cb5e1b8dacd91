// side_colours PICTURE.png (both|front|ramp|high|checker)
//
// Counts the pixels of a picture of the view tool that show the front side's
// colour (blue: blue well above red) and the back side's (orange: red above
// green well above blue), whatever the shading did to their brightness, and
// checks what a surface must show: "both" sides' colours (each on at least 2 %
// of the picture: a one-sided surface, or a two-sided one seen from both sides),
// or the "front" only (on at least 5 %, the back's on under 0.1 %: a closed
// surface whose faces point outwards). With "ramp", a picture coloured by a
// scalar (`view --scalar`) must show both ends of the colour ramp, each on at
// least 0.2 %: its dark violet (red and blue above green) and its yellow (red
// and green alike, well above blue), which neither side colour nor any edge
// colour passes for; with "high", its yellow end only (at least 0.2 %, the
// violet on under 0.01 %: a field positive on every side in sight). With "checker", a picture of `view --uv-checker` must
// show both colours of its squares, each on at least 1 %: the dark blue (as
// the front's) and the cream (red and green above blue, neither orange nor
// the ramp's yellow).
// Prints {"pixels":N,"front":F,"back":B,"low":L,"high":H,"cream":C} and exits 0 if the
// check holds, 1 if not, 2 if the picture cannot be read.
#include <QImage>

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char* argv[])
{
  const std::string expect = argc == 3 ? argv[2] : "";
  if (expect != "both" && expect != "front" && expect != "ramp" && expect != "high" && expect != "checker") {
    std::cerr << "usage: side_colours PICTURE.png (both|front|ramp|high|checker)\n";
    return 2;
  }
  const QImage image(QString::fromLocal8Bit(argv[1]));
  if (image.isNull()) {
    std::cerr << "side_colours: cannot read " << argv[1] << "\n";
    return 2;
  }
  long front = 0, back = 0, low = 0, high = 0, cream = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const QColor c = image.pixelColor(x, y);
      const int r = c.red(), g = c.green(), b = c.blue();
      front += b > r + 40 && b > g + 20;
      back += r > g + 20 && g > b + 30;
      low += r > g + 20 && b > g + 20 && b > 25;
      high += r > b + 80 && g > b + 80 && std::abs(r - g) < 40;
      cream += r > b + 10 && g > b + 5 && std::abs(r - g) < 25 && b > 60;
    }
  const long pixels = long(image.width()) * image.height();
  std::cout << "{\"pixels\":" << pixels << ",\"front\":" << front << ",\"back\":" << back << ",\"low\":" << low
            << ",\"high\":" << high << ",\"cream\":" << cream << "}" << std::endl;
  const double f = double(front) / double(pixels), b = double(back) / double(pixels);
  const double l = double(low) / double(pixels), h = double(high) / double(pixels);
  const double c = double(cream) / double(pixels);
  const bool ok = expect == "both"    ? std::min(f, b) >= 0.02
                  : expect == "front" ? f >= 0.05 && b < 0.001
                  : expect == "ramp"  ? std::min(l, h) >= 0.002
                  : expect == "high"  ? h >= 0.002 && l < 0.0001
                                      : std::min(f, c) >= 0.01;
  return ok ? 0 : 1;
}
