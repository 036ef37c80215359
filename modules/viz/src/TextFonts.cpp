// TextFonts.h: fontconfig's match for the characters of a text, kept per character set.
#include "TextFonts.h"

#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <fontconfig/fontconfig.h>

#include <QHash>
#include <QMutex>

#include <algorithm>

namespace vsim::viz {
namespace {

bool latin1Only(const QString& text)
{
    return std::all_of(text.begin(), text.end(), [](QChar c) { return c.unicode() < 0x100; });
}

/// The characters beyond Latin-1, sorted and unique: the key of the match cache.
QString charactersBeyondLatin1(const QString& text)
{
    QList<char32_t> characters;
    for (char32_t c : text.toUcs4())
        if (c >= 0x100 && !characters.contains(c))
            characters.append(c);
    std::sort(characters.begin(), characters.end());
    return QString::fromUcs4(characters.constData(), characters.size());
}

QString matchFontFile(const QString& characters)
{
    if (!FcInit())
        return {};
    FcPattern* pattern = FcNameParse(reinterpret_cast<const FcChar8*>("sans-serif"));
    FcCharSet* wanted = FcCharSetCreate();
    for (char32_t c : characters.toUcs4())
        FcCharSetAddChar(wanted, c);
    FcPatternAddCharSet(pattern, FC_CHARSET, wanted);
    FcConfigSubstitute(nullptr, pattern, FcMatchPattern);
    FcDefaultSubstitute(pattern);
    FcResult result = FcResultNoMatch;
    FcPattern* match = FcFontMatch(nullptr, pattern, &result);
    QString file;
    FcCharSet* covered = nullptr;
    FcChar8* path = nullptr;
    if (match && FcPatternGetCharSet(match, FC_CHARSET, 0, &covered) == FcResultMatch &&
        FcCharSetIsSubset(wanted, covered) && FcPatternGetString(match, FC_FILE, 0, &path) == FcResultMatch)
        file = QString::fromUtf8(reinterpret_cast<const char*>(path));
    if (match)
        FcPatternDestroy(match);
    FcCharSetDestroy(wanted);
    FcPatternDestroy(pattern);
    return file;
}

} // namespace

QString fontFileCovering(const QString& text)
{
    static QMutex mutex;
    static QHash<QString, QString> matched;
    const QString key = charactersBeyondLatin1(text);
    const QMutexLocker lock(&mutex);
    auto found = matched.find(key);
    if (found == matched.end())
        found = matched.insert(key, matchFontFile(key));
    return *found;
}

void fitFontToText(vtkTextProperty* property, const QString& text)
{
    const QString file = latin1Only(text) ? QString() : fontFileCovering(text);
    if (file.isEmpty())
    {
        if (property->GetFontFamily() == VTK_FONT_FILE)
            property->SetFontFamilyToArial();
        return;
    }
    property->SetFontFamily(VTK_FONT_FILE);
    property->SetFontFile(file.toUtf8().constData());
}

void setActorText(vtkTextActor* actor, const QString& text)
{
    fitFontToText(actor->GetTextProperty(), text);
    actor->SetInput(text.toUtf8().constData());
}

} // namespace vsim::viz
