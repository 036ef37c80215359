#include "vsim/viz/DecimalText.h"

#include <QLocale>

#include <cmath>

namespace vsim::viz {
namespace {

QLocale readerLocale()
{
    QLocale locale;
    locale.setNumberOptions(QLocale::OmitGroupSeparator);
    return locale;
}

} // namespace

QString decimalText(double value, int decimals)
{
    if (std::abs(value) < 0.5 * std::pow(10.0, -decimals))
        value = 0.0; // "-0.0" would read as a sign that means something
    return readerLocale().toString(value, 'f', decimals);
}

QString significantText(double value, int digits)
{
    return readerLocale().toString(value, 'g', digits);
}

} // namespace vsim::viz
