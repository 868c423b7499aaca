// Proof that lcm-spy will decode every channel: loads lcmtypes_sdlqr.jar next to LCM's lcm.jar,
// finds our types by their LCM fingerprint (as lcm-spy does), and decodes the first message of
// every channel of a recorded log with the generated Java class.
//
//   java -cp /usr/share/java/lcm.jar:lcmtypes_sdlqr.jar:CLASSDIR DecodeCheck JAR LOG [EXPECTED_TYPES]
//
// Exit code 0 when every channel decodes (and the jar holds EXPECTED_TYPES types), else 1.

import java.io.File;
import java.lang.reflect.Field;
import java.util.Enumeration;
import java.util.HashMap;
import java.util.Map;
import java.util.TreeMap;
import java.util.jar.JarEntry;
import java.util.jar.JarFile;

import lcm.lcm.LCMEncodable;
import lcm.logging.Log;

public class DecodeCheck {
  public static void main(String[] args) throws Exception {
    if (args.length < 2) {
      System.err.println("usage: DecodeCheck JAR LOG [EXPECTED_TYPES]");
      System.exit(2);
    }
    Map<Long, Class<?>> types = new HashMap<>();
    try (JarFile jar = new JarFile(args[0])) {
      for (Enumeration<JarEntry> e = jar.entries(); e.hasMoreElements();) {
        String name = e.nextElement().getName();
        if (!name.endsWith(".class") || name.contains("$")) continue;
        Class<?> cls = Class.forName(name.substring(0, name.length() - 6).replace('/', '.'));
        if (!LCMEncodable.class.isAssignableFrom(cls)) continue;
        Field fingerprint = cls.getField("LCM_FINGERPRINT");
        types.put(fingerprint.getLong(null), cls);
      }
    }
    System.out.println("Found " + types.size() + " LCM types in " + args[0]);
    int failures = 0;
    if (args.length > 2 && types.size() != Integer.parseInt(args[2])) {
      System.out.println("FAIL expected " + args[2] + " types");
      failures++;
    }

    Map<String, String> decoded = new TreeMap<>();
    Log log = new Log(args[1], "r");
    try {
      while (true) {
        Log.Event event = log.readNext();
        // LCM's own start-up self test (liblcm publishes it on every new bus connection).
        if (decoded.containsKey(event.channel) || event.channel.equals("LCM_SELF_TEST")) continue;
        long fingerprint = 0;
        for (int i = 0; i < 8 && i < event.data.length; i++) fingerprint = (fingerprint << 8) | (event.data[i] & 0xff);
        Class<?> cls = types.get(fingerprint);
        if (cls == null) {
          decoded.put(event.channel, null);
          continue;
        }
        Object message = cls.getConstructor(byte[].class).newInstance((Object) event.data);
        decoded.put(event.channel, cls.getSimpleName() + " " + describe(message));
      }
    } catch (java.io.EOFException end) {
      // the end of the log
    } finally {
      log.close();
    }
    for (Map.Entry<String, String> e : decoded.entrySet()) {
      if (e.getValue() == null) {
        System.out.println("FAIL " + e.getKey() + ": no type in the jar has its fingerprint");
        failures++;
      } else {
        System.out.println("  " + e.getKey() + ": " + e.getValue());
      }
    }
    System.out.println("decoded the first message of " + (decoded.size() - failures) + " of " + decoded.size()
                       + " channels");
    System.exit(failures == 0 && !decoded.isEmpty() ? 0 : 1);
  }

  // utime, seq and, for a gain message, the first row of K.
  private static String describe(Object message) throws Exception {
    StringBuilder text = new StringBuilder();
    text.append("utime=").append(message.getClass().getField("utime").getLong(message));
    text.append(" seq=").append(message.getClass().getField("seq").getLong(message));
    try {
      double[] k = (double[]) message.getClass().getField("K").get(message);
      text.append(" K[0..9]=");
      for (int i = 0; i < 10; i++) text.append(i == 0 ? "" : ",").append(String.format("%.3g", k[i]));
    } catch (NoSuchFieldException none) {
      // not a gain message
    }
    return text.toString();
  }
}
