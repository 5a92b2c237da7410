// Text from input files as data: printable() escapes what a terminal would obey or misprint, and
// name_fault() says which names no export can write as they are. Expected strings are written
// out by hand.

#include <QtTest>

#include <string>

#include "engine/core/error.h"
#include "engine/core/text.h"

using namespace garment;

class TextTest : public QObject {
  Q_OBJECT
 private slots:
  void printable_escapes_controls_and_invalid_utf8_data() {
    QTest::addColumn<QByteArray>("input");
    QTest::addColumn<QByteArray>("expected");
    QTest::newRow("plain ASCII") << QByteArray("front_panel 2") << QByteArray("front_panel 2");
    QTest::newRow("UTF-8 kept") << QByteArray(
                                       "d\xc3\xa9"
                                       "collet\xc3\xa9 \xe2\x9c\x82")
                                << QByteArray(
                                       "d\xc3\xa9"
                                       "collet\xc3\xa9 \xe2\x9c\x82");
    QTest::newRow("newline, tab, CR")
        << QByteArray("a\nb\tc\r") << QByteArray("a\\x0ab\\x09c\\x0d");
    QTest::newRow("NUL") << QByteArray("a\0b", 3) << QByteArray("a\\x00b");
    QTest::newRow("ESC sequence") << QByteArray("\x1b[2J") << QByteArray("\\x1b[2J");
    QTest::newRow("DEL") << QByteArray("a\x7f") << QByteArray("a\\x7f");
    QTest::newRow("C1 NEL U+0085") << QByteArray("a\xc2\x85z") << QByteArray("a\\xc2\\x85z");
    QTest::newRow("line separator U+2028")
        << QByteArray("a\xe2\x80\xa8z") << QByteArray("a\\xe2\\x80\\xa8z");
    QTest::newRow("stray bytes") << QByteArray("fr\xff\xfent") << QByteArray("fr\\xff\\xfent");
    QTest::newRow("overlong slash") << QByteArray("\xc0\xaf") << QByteArray("\\xc0\\xaf");
    QTest::newRow("surrogate U+D800")
        << QByteArray("\xed\xa0\x80") << QByteArray("\\xed\\xa0\\x80");
    QTest::newRow("cut short") << QByteArray("ab\xe2\x9c") << QByteArray("ab\\xe2\\x9c");
    QTest::newRow("beyond U+10FFFF")
        << QByteArray("\xf4\x90\x80\x80") << QByteArray("\\xf4\\x90\\x80\\x80");
    QTest::newRow("4-byte emoji kept")
        << QByteArray("\xf0\x9f\x91\x95") << QByteArray("\xf0\x9f\x91\x95");
  }
  void printable_escapes_controls_and_invalid_utf8() {
    QFETCH(QByteArray, input);
    QFETCH(QByteArray, expected);
    const std::string once = printable(input.toStdString());
    QCOMPARE(QByteArray::fromStdString(once), expected);
    QCOMPARE(QByteArray::fromStdString(printable(once)), expected);  // escaping twice is harmless
  }

  void name_fault_data() {
    QTest::addColumn<QByteArray>("name");
    QTest::addColumn<QString>("fault");
    QTest::newRow("plain") << QByteArray("front") << QString();
    QTest::newRow("inner space") << QByteArray("left sleeve") << QString();
    QTest::newRow("UTF-8") << QByteArray("manche_\xc3\xa0_gauche") << QString();
    QTest::newRow("empty") << QByteArray() << QString("the name is empty");
    QTest::newRow("newline") << QByteArray("front\nv 0 0 0")
                             << QString("the name contains the control character \\x0a");
    QTest::newRow("NUL") << QByteArray("fr\0ont", 6)
                         << QString("the name contains the control character \\x00");
    QTest::newRow("ESC") << QByteArray("\x1b[2J")
                         << QString("the name contains the control character \\x1b");
    QTest::newRow("line separator") << QByteArray("a\xe2\x80\xa8z")
                                    << QString(
                                           "the name contains the control character "
                                           "\\xe2\\x80\\xa8");
    QTest::newRow("invalid UTF-8")
        << QByteArray("fr\xffont") << QString("the name is not valid UTF-8");
    QTest::newRow("leading space")
        << QByteArray(" front")
        << QString("the name begins or ends with a space, which an OBJ `g` line does not keep");
    QTest::newRow("trailing space")
        << QByteArray("front ")
        << QString("the name begins or ends with a space, which an OBJ `g` line does not keep");
  }
  void name_fault() {
    QFETCH(QByteArray, name);
    QFETCH(QString, fault);
    QCOMPARE(QString::fromStdString(garment::name_fault(name.toStdString())), fault);
  }

  // The one place messages are assembled escapes what the input put into place and message; the
  // file's path is the user's own and stays as given.
  void input_errors_escape_quoted_text() {
    try {
      throw_input_error("p.json", "panel '\x1b[31mred'", "value '\x07\n'");
      QFAIL("no error");
    } catch (const InputError& error) {
      QCOMPARE(QByteArray(error.what()),
               QByteArray("p.json: panel '\\x1b[31mred': value '\\x07\\x0a'"));
    }
  }
};

QTEST_APPLESS_MAIN(TextTest)
#include "test_text.moc"
