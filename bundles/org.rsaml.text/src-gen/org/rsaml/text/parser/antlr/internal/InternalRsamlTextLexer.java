package org.rsaml.text.parser.antlr.internal;

// Hack: Use our own Lexer superclass by means of import. 
// Currently there is no other way to specify the superclass for the lexer.
import org.eclipse.xtext.parser.antlr.Lexer;


import org.antlr.runtime.*;
import java.util.Stack;
import java.util.List;
import java.util.ArrayList;

@SuppressWarnings("all")
public class InternalRsamlTextLexer extends Lexer {
    public static final int T__50=50;
    public static final int T__59=59;
    public static final int T__55=55;
    public static final int T__56=56;
    public static final int T__57=57;
    public static final int T__58=58;
    public static final int T__51=51;
    public static final int T__52=52;
    public static final int T__53=53;
    public static final int T__54=54;
    public static final int T__60=60;
    public static final int T__61=61;
    public static final int RULE_ID=5;
    public static final int T__66=66;
    public static final int RULE_ML_COMMENT=7;
    public static final int T__67=67;
    public static final int T__68=68;
    public static final int T__69=69;
    public static final int T__62=62;
    public static final int T__63=63;
    public static final int T__64=64;
    public static final int T__65=65;
    public static final int T__37=37;
    public static final int T__38=38;
    public static final int T__39=39;
    public static final int T__33=33;
    public static final int T__34=34;
    public static final int T__35=35;
    public static final int T__36=36;
    public static final int T__30=30;
    public static final int T__31=31;
    public static final int T__32=32;
    public static final int T__48=48;
    public static final int T__49=49;
    public static final int T__44=44;
    public static final int T__45=45;
    public static final int T__46=46;
    public static final int T__47=47;
    public static final int T__40=40;
    public static final int T__41=41;
    public static final int T__42=42;
    public static final int T__43=43;
    public static final int T__91=91;
    public static final int T__100=100;
    public static final int T__92=92;
    public static final int T__93=93;
    public static final int T__102=102;
    public static final int T__94=94;
    public static final int T__101=101;
    public static final int T__90=90;
    public static final int T__19=19;
    public static final int T__15=15;
    public static final int T__16=16;
    public static final int T__17=17;
    public static final int T__18=18;
    public static final int T__11=11;
    public static final int T__99=99;
    public static final int T__12=12;
    public static final int T__13=13;
    public static final int T__14=14;
    public static final int T__95=95;
    public static final int T__96=96;
    public static final int T__97=97;
    public static final int T__98=98;
    public static final int T__26=26;
    public static final int T__27=27;
    public static final int T__28=28;
    public static final int T__29=29;
    public static final int T__22=22;
    public static final int T__23=23;
    public static final int T__24=24;
    public static final int T__25=25;
    public static final int T__20=20;
    public static final int T__21=21;
    public static final int T__70=70;
    public static final int T__71=71;
    public static final int T__72=72;
    public static final int RULE_STRING=4;
    public static final int RULE_SL_COMMENT=8;
    public static final int T__77=77;
    public static final int T__119=119;
    public static final int T__78=78;
    public static final int T__118=118;
    public static final int T__79=79;
    public static final int T__73=73;
    public static final int T__115=115;
    public static final int EOF=-1;
    public static final int T__74=74;
    public static final int T__114=114;
    public static final int T__75=75;
    public static final int T__117=117;
    public static final int T__76=76;
    public static final int T__116=116;
    public static final int T__80=80;
    public static final int T__111=111;
    public static final int T__81=81;
    public static final int T__110=110;
    public static final int T__82=82;
    public static final int T__113=113;
    public static final int T__83=83;
    public static final int T__112=112;
    public static final int RULE_WS=9;
    public static final int RULE_ANY_OTHER=10;
    public static final int RULE_NUMBER=6;
    public static final int T__88=88;
    public static final int T__108=108;
    public static final int T__89=89;
    public static final int T__107=107;
    public static final int T__109=109;
    public static final int T__84=84;
    public static final int T__104=104;
    public static final int T__85=85;
    public static final int T__103=103;
    public static final int T__86=86;
    public static final int T__106=106;
    public static final int T__87=87;
    public static final int T__105=105;

    // delegates
    // delegators

    public InternalRsamlTextLexer() {;} 
    public InternalRsamlTextLexer(CharStream input) {
        this(input, new RecognizerSharedState());
    }
    public InternalRsamlTextLexer(CharStream input, RecognizerSharedState state) {
        super(input,state);

    }
    public String getGrammarFileName() { return "InternalRsamlText.g"; }

    // $ANTLR start "T__11"
    public final void mT__11() throws RecognitionException {
        try {
            int _type = T__11;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:11:7: ( 'architecture' )
            // InternalRsamlText.g:11:9: 'architecture'
            {
            match("architecture"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__11"

    // $ANTLR start "T__12"
    public final void mT__12() throws RecognitionException {
        try {
            int _type = T__12;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:12:7: ( '{' )
            // InternalRsamlText.g:12:9: '{'
            {
            match('{'); 

            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__12"

    // $ANTLR start "T__13"
    public final void mT__13() throws RecognitionException {
        try {
            int _type = T__13;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:13:7: ( 'category' )
            // InternalRsamlText.g:13:9: 'category'
            {
            match("category"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__13"

    // $ANTLR start "T__14"
    public final void mT__14() throws RecognitionException {
        try {
            int _type = T__14;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:14:7: ( 'declaredLayers' )
            // InternalRsamlText.g:14:9: 'declaredLayers'
            {
            match("declaredLayers"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__14"

    // $ANTLR start "T__15"
    public final void mT__15() throws RecognitionException {
        try {
            int _type = T__15;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:15:7: ( 'lifecycle' )
            // InternalRsamlText.g:15:9: 'lifecycle'
            {
            match("lifecycle"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__15"

    // $ANTLR start "T__16"
    public final void mT__16() throws RecognitionException {
        try {
            int _type = T__16;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:16:7: ( 'packages' )
            // InternalRsamlText.g:16:9: 'packages'
            {
            match("packages"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__16"

    // $ANTLR start "T__17"
    public final void mT__17() throws RecognitionException {
        try {
            int _type = T__17;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:17:7: ( '}' )
            // InternalRsamlText.g:17:9: '}'
            {
            match('}'); 

            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__17"

    // $ANTLR start "T__18"
    public final void mT__18() throws RecognitionException {
        try {
            int _type = T__18;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:18:7: ( 'description' )
            // InternalRsamlText.g:18:9: 'description'
            {
            match("description"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__18"

    // $ANTLR start "T__19"
    public final void mT__19() throws RecognitionException {
        try {
            int _type = T__19;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:19:7: ( 'unit' )
            // InternalRsamlText.g:19:9: 'unit'
            {
            match("unit"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__19"

    // $ANTLR start "T__20"
    public final void mT__20() throws RecognitionException {
        try {
            int _type = T__20;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:20:7: ( 'type' )
            // InternalRsamlText.g:20:9: 'type'
            {
            match("type"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__20"

    // $ANTLR start "T__21"
    public final void mT__21() throws RecognitionException {
        try {
            int _type = T__21;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:21:7: ( 'execType' )
            // InternalRsamlText.g:21:9: 'execType'
            {
            match("execType"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__21"

    // $ANTLR start "T__22"
    public final void mT__22() throws RecognitionException {
        try {
            int _type = T__22;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:22:7: ( 'period' )
            // InternalRsamlText.g:22:9: 'period'
            {
            match("period"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__22"

    // $ANTLR start "T__23"
    public final void mT__23() throws RecognitionException {
        try {
            int _type = T__23;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:23:7: ( 'deadline' )
            // InternalRsamlText.g:23:9: 'deadline'
            {
            match("deadline"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__23"

    // $ANTLR start "T__24"
    public final void mT__24() throws RecognitionException {
        try {
            int _type = T__24;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:24:7: ( 'wcet' )
            // InternalRsamlText.g:24:9: 'wcet'
            {
            match("wcet"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__24"

    // $ANTLR start "T__25"
    public final void mT__25() throws RecognitionException {
        try {
            int _type = T__25;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:25:7: ( 'layer' )
            // InternalRsamlText.g:25:9: 'layer'
            {
            match("layer"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__25"

    // $ANTLR start "T__26"
    public final void mT__26() throws RecognitionException {
        try {
            int _type = T__26;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:26:7: ( 'level' )
            // InternalRsamlText.g:26:9: 'level'
            {
            match("level"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__26"

    // $ANTLR start "T__27"
    public final void mT__27() throws RecognitionException {
        try {
            int _type = T__27;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:27:7: ( 'maxExecTime' )
            // InternalRsamlText.g:27:9: 'maxExecTime'
            {
            match("maxExecTime"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__27"

    // $ANTLR start "T__28"
    public final void mT__28() throws RecognitionException {
        try {
            int _type = T__28;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:28:7: ( 'module' )
            // InternalRsamlText.g:28:9: 'module'
            {
            match("module"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__28"

    // $ANTLR start "T__29"
    public final void mT__29() throws RecognitionException {
        try {
            int _type = T__29;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:29:7: ( 'sensors' )
            // InternalRsamlText.g:29:9: 'sensors'
            {
            match("sensors"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__29"

    // $ANTLR start "T__30"
    public final void mT__30() throws RecognitionException {
        try {
            int _type = T__30;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:30:7: ( ',' )
            // InternalRsamlText.g:30:9: ','
            {
            match(','); 

            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__30"

    // $ANTLR start "T__31"
    public final void mT__31() throws RecognitionException {
        try {
            int _type = T__31;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:31:7: ( 'actuators' )
            // InternalRsamlText.g:31:9: 'actuators'
            {
            match("actuators"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__31"

    // $ANTLR start "T__32"
    public final void mT__32() throws RecognitionException {
        try {
            int _type = T__32;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:32:7: ( 'function' )
            // InternalRsamlText.g:32:9: 'function'
            {
            match("function"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__32"

    // $ANTLR start "T__33"
    public final void mT__33() throws RecognitionException {
        try {
            int _type = T__33;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:33:7: ( 'synchroType' )
            // InternalRsamlText.g:33:9: 'synchroType'
            {
            match("synchroType"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__33"

    // $ANTLR start "T__34"
    public final void mT__34() throws RecognitionException {
        try {
            int _type = T__34;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:34:7: ( 'schedPolicy' )
            // InternalRsamlText.g:34:9: 'schedPolicy'
            {
            match("schedPolicy"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__34"

    // $ANTLR start "T__35"
    public final void mT__35() throws RecognitionException {
        try {
            int _type = T__35;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:35:7: ( 'otherPolicy' )
            // InternalRsamlText.g:35:9: 'otherPolicy'
            {
            match("otherPolicy"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__35"

    // $ANTLR start "T__36"
    public final void mT__36() throws RecognitionException {
        try {
            int _type = T__36;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:36:7: ( 'action' )
            // InternalRsamlText.g:36:9: 'action'
            {
            match("action"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__36"

    // $ANTLR start "T__37"
    public final void mT__37() throws RecognitionException {
        try {
            int _type = T__37;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:37:7: ( 'rtAction' )
            // InternalRsamlText.g:37:9: 'rtAction'
            {
            match("rtAction"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__37"

    // $ANTLR start "T__38"
    public final void mT__38() throws RecognitionException {
        try {
            int _type = T__38;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:38:7: ( 'start' )
            // InternalRsamlText.g:38:9: 'start'
            {
            match("start"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__38"

    // $ANTLR start "T__39"
    public final void mT__39() throws RecognitionException {
        try {
            int _type = T__39;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:39:7: ( 'input' )
            // InternalRsamlText.g:39:9: 'input'
            {
            match("input"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__39"

    // $ANTLR start "T__40"
    public final void mT__40() throws RecognitionException {
        try {
            int _type = T__40;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:40:7: ( 'output' )
            // InternalRsamlText.g:40:9: 'output'
            {
            match("output"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__40"

    // $ANTLR start "T__41"
    public final void mT__41() throws RecognitionException {
        try {
            int _type = T__41;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:41:7: ( 'dataType' )
            // InternalRsamlText.g:41:9: 'dataType'
            {
            match("dataType"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__41"

    // $ANTLR start "T__42"
    public final void mT__42() throws RecognitionException {
        try {
            int _type = T__42;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:42:7: ( 'messageType' )
            // InternalRsamlText.g:42:9: 'messageType'
            {
            match("messageType"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__42"

    // $ANTLR start "T__43"
    public final void mT__43() throws RecognitionException {
        try {
            int _type = T__43;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:43:7: ( 'topic' )
            // InternalRsamlText.g:43:9: 'topic'
            {
            match("topic"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__43"

    // $ANTLR start "T__44"
    public final void mT__44() throws RecognitionException {
        try {
            int _type = T__44;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:44:7: ( 'connect' )
            // InternalRsamlText.g:44:9: 'connect'
            {
            match("connect"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__44"

    // $ANTLR start "T__45"
    public final void mT__45() throws RecognitionException {
        try {
            int _type = T__45;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:45:7: ( '->' )
            // InternalRsamlText.g:45:9: '->'
            {
            match("->"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__45"

    // $ANTLR start "T__46"
    public final void mT__46() throws RecognitionException {
        try {
            int _type = T__46;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:46:7: ( 'inhibitor' )
            // InternalRsamlText.g:46:9: 'inhibitor'
            {
            match("inhibitor"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__46"

    // $ANTLR start "T__47"
    public final void mT__47() throws RecognitionException {
        try {
            int _type = T__47;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:47:7: ( 'trigger' )
            // InternalRsamlText.g:47:9: 'trigger'
            {
            match("trigger"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__47"

    // $ANTLR start "T__48"
    public final void mT__48() throws RecognitionException {
        try {
            int _type = T__48;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:48:7: ( 'target' )
            // InternalRsamlText.g:48:9: 'target'
            {
            match("target"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__48"

    // $ANTLR start "T__49"
    public final void mT__49() throws RecognitionException {
        try {
            int _type = T__49;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:49:7: ( 'duration' )
            // InternalRsamlText.g:49:9: 'duration'
            {
            match("duration"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__49"

    // $ANTLR start "T__50"
    public final void mT__50() throws RecognitionException {
        try {
            int _type = T__50;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:50:7: ( 'suppressor' )
            // InternalRsamlText.g:50:9: 'suppressor'
            {
            match("suppressor"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__50"

    // $ANTLR start "T__51"
    public final void mT__51() throws RecognitionException {
        try {
            int _type = T__51;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:51:7: ( 'sensor' )
            // InternalRsamlText.g:51:9: 'sensor'
            {
            match("sensor"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__51"

    // $ANTLR start "T__52"
    public final void mT__52() throws RecognitionException {
        try {
            int _type = T__52;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:52:7: ( 'kind' )
            // InternalRsamlText.g:52:9: 'kind'
            {
            match("kind"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__52"

    // $ANTLR start "T__53"
    public final void mT__53() throws RecognitionException {
        try {
            int _type = T__53;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:53:7: ( 'actuator' )
            // InternalRsamlText.g:53:9: 'actuator'
            {
            match("actuator"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__53"

    // $ANTLR start "T__54"
    public final void mT__54() throws RecognitionException {
        try {
            int _type = T__54;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:54:7: ( 'mission' )
            // InternalRsamlText.g:54:9: 'mission'
            {
            match("mission"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__54"

    // $ANTLR start "T__55"
    public final void mT__55() throws RecognitionException {
        try {
            int _type = T__55;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:55:7: ( 'goal' )
            // InternalRsamlText.g:55:9: 'goal'
            {
            match("goal"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__55"

    // $ANTLR start "T__56"
    public final void mT__56() throws RecognitionException {
        try {
            int _type = T__56;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:56:7: ( 'priority' )
            // InternalRsamlText.g:56:9: 'priority'
            {
            match("priority"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__56"

    // $ANTLR start "T__57"
    public final void mT__57() throws RecognitionException {
        try {
            int _type = T__57;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:57:7: ( 'plan' )
            // InternalRsamlText.g:57:9: 'plan'
            {
            match("plan"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__57"

    // $ANTLR start "T__58"
    public final void mT__58() throws RecognitionException {
        try {
            int _type = T__58;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:58:7: ( 'achieves' )
            // InternalRsamlText.g:58:9: 'achieves'
            {
            match("achieves"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__58"

    // $ANTLR start "T__59"
    public final void mT__59() throws RecognitionException {
        try {
            int _type = T__59;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:59:7: ( 'activity' )
            // InternalRsamlText.g:59:9: 'activity'
            {
            match("activity"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__59"

    // $ANTLR start "T__60"
    public final void mT__60() throws RecognitionException {
        try {
            int _type = T__60;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:60:7: ( 'actions' )
            // InternalRsamlText.g:60:9: 'actions'
            {
            match("actions"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__60"

    // $ANTLR start "T__61"
    public final void mT__61() throws RecognitionException {
        try {
            int _type = T__61;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:61:7: ( 'supervisor' )
            // InternalRsamlText.g:61:9: 'supervisor'
            {
            match("supervisor"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__61"

    // $ANTLR start "T__62"
    public final void mT__62() throws RecognitionException {
        try {
            int _type = T__62;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:62:7: ( 'plans' )
            // InternalRsamlText.g:62:9: 'plans'
            {
            match("plans"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__62"

    // $ANTLR start "T__63"
    public final void mT__63() throws RecognitionException {
        try {
            int _type = T__63;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:63:7: ( 'realisedBy' )
            // InternalRsamlText.g:63:9: 'realisedBy'
            {
            match("realisedBy"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__63"

    // $ANTLR start "T__64"
    public final void mT__64() throws RecognitionException {
        try {
            int _type = T__64;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:64:7: ( 'order' )
            // InternalRsamlText.g:64:9: 'order'
            {
            match("order"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__64"

    // $ANTLR start "T__65"
    public final void mT__65() throws RecognitionException {
        try {
            int _type = T__65;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:65:7: ( 'issuer' )
            // InternalRsamlText.g:65:9: 'issuer'
            {
            match("issuer"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__65"

    // $ANTLR start "T__66"
    public final void mT__66() throws RecognitionException {
        try {
            int _type = T__66;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:66:7: ( 'receiver' )
            // InternalRsamlText.g:66:9: 'receiver'
            {
            match("receiver"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__66"

    // $ANTLR start "T__67"
    public final void mT__67() throws RecognitionException {
        try {
            int _type = T__67;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:67:7: ( 'requests' )
            // InternalRsamlText.g:67:9: 'requests'
            {
            match("requests"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__67"

    // $ANTLR start "T__68"
    public final void mT__68() throws RecognitionException {
        try {
            int _type = T__68;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:68:7: ( 'database' )
            // InternalRsamlText.g:68:9: 'database'
            {
            match("database"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__68"

    // $ANTLR start "T__69"
    public final void mT__69() throws RecognitionException {
        try {
            int _type = T__69;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:69:7: ( 'knowledge' )
            // InternalRsamlText.g:69:9: 'knowledge'
            {
            match("knowledge"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__69"

    // $ANTLR start "T__70"
    public final void mT__70() throws RecognitionException {
        try {
            int _type = T__70;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:70:7: ( 'usedBy' )
            // InternalRsamlText.g:70:9: 'usedBy'
            {
            match("usedBy"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__70"

    // $ANTLR start "T__71"
    public final void mT__71() throws RecognitionException {
        try {
            int _type = T__71;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:71:7: ( 'processor' )
            // InternalRsamlText.g:71:9: 'processor'
            {
            match("processor"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__71"

    // $ANTLR start "T__72"
    public final void mT__72() throws RecognitionException {
        try {
            int _type = T__72;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:72:7: ( 'core' )
            // InternalRsamlText.g:72:9: 'core'
            {
            match("core"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__72"

    // $ANTLR start "T__73"
    public final void mT__73() throws RecognitionException {
        try {
            int _type = T__73;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:73:7: ( 'host' )
            // InternalRsamlText.g:73:9: 'host'
            {
            match("host"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__73"

    // $ANTLR start "T__74"
    public final void mT__74() throws RecognitionException {
        try {
            int _type = T__74;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:74:7: ( 'linkLatency' )
            // InternalRsamlText.g:74:9: 'linkLatency'
            {
            match("linkLatency"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__74"

    // $ANTLR start "T__75"
    public final void mT__75() throws RecognitionException {
        try {
            int _type = T__75;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:75:7: ( 'modules' )
            // InternalRsamlText.g:75:9: 'modules'
            {
            match("modules"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__75"

    // $ANTLR start "T__76"
    public final void mT__76() throws RecognitionException {
        try {
            int _type = T__76;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:76:7: ( 'latency' )
            // InternalRsamlText.g:76:9: 'latency'
            {
            match("latency"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__76"

    // $ANTLR start "T__77"
    public final void mT__77() throws RecognitionException {
        try {
            int _type = T__77;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:77:7: ( 'from' )
            // InternalRsamlText.g:77:9: 'from'
            {
            match("from"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__77"

    // $ANTLR start "T__78"
    public final void mT__78() throws RecognitionException {
        try {
            int _type = T__78;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:78:7: ( 'to' )
            // InternalRsamlText.g:78:9: 'to'
            {
            match("to"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__78"

    // $ANTLR start "T__79"
    public final void mT__79() throws RecognitionException {
        try {
            int _type = T__79;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:79:7: ( 'via' )
            // InternalRsamlText.g:79:9: 'via'
            {
            match("via"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__79"

    // $ANTLR start "T__80"
    public final void mT__80() throws RecognitionException {
        try {
            int _type = T__80;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:80:7: ( 'maxLatency' )
            // InternalRsamlText.g:80:9: 'maxLatency'
            {
            match("maxLatency"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__80"

    // $ANTLR start "T__81"
    public final void mT__81() throws RecognitionException {
        try {
            int _type = T__81;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:81:7: ( '.' )
            // InternalRsamlText.g:81:9: '.'
            {
            match('.'); 

            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__81"

    // $ANTLR start "T__82"
    public final void mT__82() throws RecognitionException {
        try {
            int _type = T__82;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:82:7: ( 'centralized' )
            // InternalRsamlText.g:82:9: 'centralized'
            {
            match("centralized"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__82"

    // $ANTLR start "T__83"
    public final void mT__83() throws RecognitionException {
        try {
            int _type = T__83;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:83:7: ( 'hierarchical' )
            // InternalRsamlText.g:83:9: 'hierarchical'
            {
            match("hierarchical"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__83"

    // $ANTLR start "T__84"
    public final void mT__84() throws RecognitionException {
        try {
            int _type = T__84;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:84:7: ( 'behavioral' )
            // InternalRsamlText.g:84:9: 'behavioral'
            {
            match("behavioral"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__84"

    // $ANTLR start "T__85"
    public final void mT__85() throws RecognitionException {
        try {
            int _type = T__85;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:85:7: ( 'hybrid' )
            // InternalRsamlText.g:85:9: 'hybrid'
            {
            match("hybrid"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__85"

    // $ANTLR start "T__86"
    public final void mT__86() throws RecognitionException {
        try {
            int _type = T__86;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:86:7: ( 'other' )
            // InternalRsamlText.g:86:9: 'other'
            {
            match("other"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__86"

    // $ANTLR start "T__87"
    public final void mT__87() throws RecognitionException {
        try {
            int _type = T__87;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:87:7: ( 'simple' )
            // InternalRsamlText.g:87:9: 'simple'
            {
            match("simple"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__87"

    // $ANTLR start "T__88"
    public final void mT__88() throws RecognitionException {
        try {
            int _type = T__88;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:88:7: ( 'realTime' )
            // InternalRsamlText.g:88:9: 'realTime'
            {
            match("realTime"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__88"

    // $ANTLR start "T__89"
    public final void mT__89() throws RecognitionException {
        try {
            int _type = T__89;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:89:7: ( 'periodic' )
            // InternalRsamlText.g:89:9: 'periodic'
            {
            match("periodic"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__89"

    // $ANTLR start "T__90"
    public final void mT__90() throws RecognitionException {
        try {
            int _type = T__90;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:90:7: ( 'sporadic' )
            // InternalRsamlText.g:90:9: 'sporadic'
            {
            match("sporadic"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__90"

    // $ANTLR start "T__91"
    public final void mT__91() throws RecognitionException {
        try {
            int _type = T__91;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:91:7: ( 'aperiodic' )
            // InternalRsamlText.g:91:9: 'aperiodic'
            {
            match("aperiodic"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__91"

    // $ANTLR start "T__92"
    public final void mT__92() throws RecognitionException {
        try {
            int _type = T__92;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:92:7: ( 'ns' )
            // InternalRsamlText.g:92:9: 'ns'
            {
            match("ns"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__92"

    // $ANTLR start "T__93"
    public final void mT__93() throws RecognitionException {
        try {
            int _type = T__93;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:93:7: ( 'us' )
            // InternalRsamlText.g:93:9: 'us'
            {
            match("us"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__93"

    // $ANTLR start "T__94"
    public final void mT__94() throws RecognitionException {
        try {
            int _type = T__94;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:94:7: ( 'ms' )
            // InternalRsamlText.g:94:9: 'ms'
            {
            match("ms"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__94"

    // $ANTLR start "T__95"
    public final void mT__95() throws RecognitionException {
        try {
            int _type = T__95;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:95:7: ( 's' )
            // InternalRsamlText.g:95:9: 's'
            {
            match('s'); 

            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__95"

    // $ANTLR start "T__96"
    public final void mT__96() throws RecognitionException {
        try {
            int _type = T__96;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:96:7: ( 'synchronous' )
            // InternalRsamlText.g:96:9: 'synchronous'
            {
            match("synchronous"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__96"

    // $ANTLR start "T__97"
    public final void mT__97() throws RecognitionException {
        try {
            int _type = T__97;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:97:7: ( 'asynchronous' )
            // InternalRsamlText.g:97:9: 'asynchronous'
            {
            match("asynchronous"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__97"

    // $ANTLR start "T__98"
    public final void mT__98() throws RecognitionException {
        try {
            int _type = T__98;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:98:7: ( 'FIFO' )
            // InternalRsamlText.g:98:9: 'FIFO'
            {
            match("FIFO"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__98"

    // $ANTLR start "T__99"
    public final void mT__99() throws RecognitionException {
        try {
            int _type = T__99;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:99:7: ( 'SJF' )
            // InternalRsamlText.g:99:9: 'SJF'
            {
            match("SJF"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__99"

    // $ANTLR start "T__100"
    public final void mT__100() throws RecognitionException {
        try {
            int _type = T__100;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:100:8: ( 'RR' )
            // InternalRsamlText.g:100:10: 'RR'
            {
            match("RR"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__100"

    // $ANTLR start "T__101"
    public final void mT__101() throws RecognitionException {
        try {
            int _type = T__101;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:101:8: ( 'RM' )
            // InternalRsamlText.g:101:10: 'RM'
            {
            match("RM"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__101"

    // $ANTLR start "T__102"
    public final void mT__102() throws RecognitionException {
        try {
            int _type = T__102;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:102:8: ( 'DM' )
            // InternalRsamlText.g:102:10: 'DM'
            {
            match("DM"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__102"

    // $ANTLR start "T__103"
    public final void mT__103() throws RecognitionException {
        try {
            int _type = T__103;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:103:8: ( 'EDF' )
            // InternalRsamlText.g:103:10: 'EDF'
            {
            match("EDF"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__103"

    // $ANTLR start "T__104"
    public final void mT__104() throws RecognitionException {
        try {
            int _type = T__104;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:104:8: ( 'LLF' )
            // InternalRsamlText.g:104:10: 'LLF'
            {
            match("LLF"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__104"

    // $ANTLR start "T__105"
    public final void mT__105() throws RecognitionException {
        try {
            int _type = T__105;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:105:8: ( 'OTHER' )
            // InternalRsamlText.g:105:10: 'OTHER'
            {
            match("OTHER"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__105"

    // $ANTLR start "T__106"
    public final void mT__106() throws RecognitionException {
        try {
            int _type = T__106;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:106:8: ( 'numeric' )
            // InternalRsamlText.g:106:10: 'numeric'
            {
            match("numeric"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__106"

    // $ANTLR start "T__107"
    public final void mT__107() throws RecognitionException {
        try {
            int _type = T__107;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:107:8: ( 'alphanumeric' )
            // InternalRsamlText.g:107:10: 'alphanumeric'
            {
            match("alphanumeric"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__107"

    // $ANTLR start "T__108"
    public final void mT__108() throws RecognitionException {
        try {
            int _type = T__108;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:108:8: ( 'boolean' )
            // InternalRsamlText.g:108:10: 'boolean'
            {
            match("boolean"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__108"

    // $ANTLR start "T__109"
    public final void mT__109() throws RecognitionException {
        try {
            int _type = T__109;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:109:8: ( 'structured' )
            // InternalRsamlText.g:109:10: 'structured'
            {
            match("structured"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__109"

    // $ANTLR start "T__110"
    public final void mT__110() throws RecognitionException {
        try {
            int _type = T__110;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:110:8: ( 'reactionTime' )
            // InternalRsamlText.g:110:10: 'reactionTime'
            {
            match("reactionTime"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__110"

    // $ANTLR start "T__111"
    public final void mT__111() throws RecognitionException {
        try {
            int _type = T__111;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:111:8: ( 'dataAge' )
            // InternalRsamlText.g:111:10: 'dataAge'
            {
            match("dataAge"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__111"

    // $ANTLR start "T__112"
    public final void mT__112() throws RecognitionException {
        try {
            int _type = T__112;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:112:8: ( 'plain' )
            // InternalRsamlText.g:112:10: 'plain'
            {
            match("plain"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__112"

    // $ANTLR start "T__113"
    public final void mT__113() throws RecognitionException {
        try {
            int _type = T__113;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:113:8: ( 'managed' )
            // InternalRsamlText.g:113:10: 'managed'
            {
            match("managed"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__113"

    // $ANTLR start "T__114"
    public final void mT__114() throws RecognitionException {
        try {
            int _type = T__114;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:114:8: ( 'single' )
            // InternalRsamlText.g:114:10: 'single'
            {
            match("single"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__114"

    // $ANTLR start "T__115"
    public final void mT__115() throws RecognitionException {
        try {
            int _type = T__115;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:115:8: ( 'perLayer' )
            // InternalRsamlText.g:115:10: 'perLayer'
            {
            match("perLayer"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__115"

    // $ANTLR start "T__116"
    public final void mT__116() throws RecognitionException {
        try {
            int _type = T__116;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:116:8: ( 'perProcessor' )
            // InternalRsamlText.g:116:10: 'perProcessor'
            {
            match("perProcessor"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__116"

    // $ANTLR start "T__117"
    public final void mT__117() throws RecognitionException {
        try {
            int _type = T__117;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:117:8: ( 'NaN' )
            // InternalRsamlText.g:117:10: 'NaN'
            {
            match("NaN"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__117"

    // $ANTLR start "T__118"
    public final void mT__118() throws RecognitionException {
        try {
            int _type = T__118;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:118:8: ( 'Infinity' )
            // InternalRsamlText.g:118:10: 'Infinity'
            {
            match("Infinity"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__118"

    // $ANTLR start "T__119"
    public final void mT__119() throws RecognitionException {
        try {
            int _type = T__119;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:119:8: ( '-' )
            // InternalRsamlText.g:119:10: '-'
            {
            match('-'); 

            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "T__119"

    // $ANTLR start "RULE_ID"
    public final void mRULE_ID() throws RecognitionException {
        try {
            int _type = RULE_ID;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:5117:9: ( ( '^' )? ( 'a' .. 'z' | 'A' .. 'Z' | '_' ) ( 'a' .. 'z' | 'A' .. 'Z' | '_' | '0' .. '9' )* )
            // InternalRsamlText.g:5117:11: ( '^' )? ( 'a' .. 'z' | 'A' .. 'Z' | '_' ) ( 'a' .. 'z' | 'A' .. 'Z' | '_' | '0' .. '9' )*
            {
            // InternalRsamlText.g:5117:11: ( '^' )?
            int alt1=2;
            int LA1_0 = input.LA(1);

            if ( (LA1_0=='^') ) {
                alt1=1;
            }
            switch (alt1) {
                case 1 :
                    // InternalRsamlText.g:5117:11: '^'
                    {
                    match('^'); 

                    }
                    break;

            }

            if ( (input.LA(1)>='A' && input.LA(1)<='Z')||input.LA(1)=='_'||(input.LA(1)>='a' && input.LA(1)<='z') ) {
                input.consume();

            }
            else {
                MismatchedSetException mse = new MismatchedSetException(null,input);
                recover(mse);
                throw mse;}

            // InternalRsamlText.g:5117:40: ( 'a' .. 'z' | 'A' .. 'Z' | '_' | '0' .. '9' )*
            loop2:
            do {
                int alt2=2;
                int LA2_0 = input.LA(1);

                if ( ((LA2_0>='0' && LA2_0<='9')||(LA2_0>='A' && LA2_0<='Z')||LA2_0=='_'||(LA2_0>='a' && LA2_0<='z')) ) {
                    alt2=1;
                }


                switch (alt2) {
            	case 1 :
            	    // InternalRsamlText.g:
            	    {
            	    if ( (input.LA(1)>='0' && input.LA(1)<='9')||(input.LA(1)>='A' && input.LA(1)<='Z')||input.LA(1)=='_'||(input.LA(1)>='a' && input.LA(1)<='z') ) {
            	        input.consume();

            	    }
            	    else {
            	        MismatchedSetException mse = new MismatchedSetException(null,input);
            	        recover(mse);
            	        throw mse;}


            	    }
            	    break;

            	default :
            	    break loop2;
                }
            } while (true);


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "RULE_ID"

    // $ANTLR start "RULE_NUMBER"
    public final void mRULE_NUMBER() throws RecognitionException {
        try {
            int _type = RULE_NUMBER;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:5119:13: ( ( '-' )? ( '0' .. '9' )+ ( '.' ( '0' .. '9' )+ )? ( ( 'e' | 'E' ) ( '+' | '-' )? ( '0' .. '9' )+ )? )
            // InternalRsamlText.g:5119:15: ( '-' )? ( '0' .. '9' )+ ( '.' ( '0' .. '9' )+ )? ( ( 'e' | 'E' ) ( '+' | '-' )? ( '0' .. '9' )+ )?
            {
            // InternalRsamlText.g:5119:15: ( '-' )?
            int alt3=2;
            int LA3_0 = input.LA(1);

            if ( (LA3_0=='-') ) {
                alt3=1;
            }
            switch (alt3) {
                case 1 :
                    // InternalRsamlText.g:5119:15: '-'
                    {
                    match('-'); 

                    }
                    break;

            }

            // InternalRsamlText.g:5119:20: ( '0' .. '9' )+
            int cnt4=0;
            loop4:
            do {
                int alt4=2;
                int LA4_0 = input.LA(1);

                if ( ((LA4_0>='0' && LA4_0<='9')) ) {
                    alt4=1;
                }


                switch (alt4) {
            	case 1 :
            	    // InternalRsamlText.g:5119:21: '0' .. '9'
            	    {
            	    matchRange('0','9'); 

            	    }
            	    break;

            	default :
            	    if ( cnt4 >= 1 ) break loop4;
                        EarlyExitException eee =
                            new EarlyExitException(4, input);
                        throw eee;
                }
                cnt4++;
            } while (true);

            // InternalRsamlText.g:5119:32: ( '.' ( '0' .. '9' )+ )?
            int alt6=2;
            int LA6_0 = input.LA(1);

            if ( (LA6_0=='.') ) {
                alt6=1;
            }
            switch (alt6) {
                case 1 :
                    // InternalRsamlText.g:5119:33: '.' ( '0' .. '9' )+
                    {
                    match('.'); 
                    // InternalRsamlText.g:5119:37: ( '0' .. '9' )+
                    int cnt5=0;
                    loop5:
                    do {
                        int alt5=2;
                        int LA5_0 = input.LA(1);

                        if ( ((LA5_0>='0' && LA5_0<='9')) ) {
                            alt5=1;
                        }


                        switch (alt5) {
                    	case 1 :
                    	    // InternalRsamlText.g:5119:38: '0' .. '9'
                    	    {
                    	    matchRange('0','9'); 

                    	    }
                    	    break;

                    	default :
                    	    if ( cnt5 >= 1 ) break loop5;
                                EarlyExitException eee =
                                    new EarlyExitException(5, input);
                                throw eee;
                        }
                        cnt5++;
                    } while (true);


                    }
                    break;

            }

            // InternalRsamlText.g:5119:51: ( ( 'e' | 'E' ) ( '+' | '-' )? ( '0' .. '9' )+ )?
            int alt9=2;
            int LA9_0 = input.LA(1);

            if ( (LA9_0=='E'||LA9_0=='e') ) {
                alt9=1;
            }
            switch (alt9) {
                case 1 :
                    // InternalRsamlText.g:5119:52: ( 'e' | 'E' ) ( '+' | '-' )? ( '0' .. '9' )+
                    {
                    if ( input.LA(1)=='E'||input.LA(1)=='e' ) {
                        input.consume();

                    }
                    else {
                        MismatchedSetException mse = new MismatchedSetException(null,input);
                        recover(mse);
                        throw mse;}

                    // InternalRsamlText.g:5119:62: ( '+' | '-' )?
                    int alt7=2;
                    int LA7_0 = input.LA(1);

                    if ( (LA7_0=='+'||LA7_0=='-') ) {
                        alt7=1;
                    }
                    switch (alt7) {
                        case 1 :
                            // InternalRsamlText.g:
                            {
                            if ( input.LA(1)=='+'||input.LA(1)=='-' ) {
                                input.consume();

                            }
                            else {
                                MismatchedSetException mse = new MismatchedSetException(null,input);
                                recover(mse);
                                throw mse;}


                            }
                            break;

                    }

                    // InternalRsamlText.g:5119:73: ( '0' .. '9' )+
                    int cnt8=0;
                    loop8:
                    do {
                        int alt8=2;
                        int LA8_0 = input.LA(1);

                        if ( ((LA8_0>='0' && LA8_0<='9')) ) {
                            alt8=1;
                        }


                        switch (alt8) {
                    	case 1 :
                    	    // InternalRsamlText.g:5119:74: '0' .. '9'
                    	    {
                    	    matchRange('0','9'); 

                    	    }
                    	    break;

                    	default :
                    	    if ( cnt8 >= 1 ) break loop8;
                                EarlyExitException eee =
                                    new EarlyExitException(8, input);
                                throw eee;
                        }
                        cnt8++;
                    } while (true);


                    }
                    break;

            }


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "RULE_NUMBER"

    // $ANTLR start "RULE_STRING"
    public final void mRULE_STRING() throws RecognitionException {
        try {
            int _type = RULE_STRING;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:5121:13: ( '\"' ( '\\\\' . | ~ ( ( '\\\\' | '\"' ) ) )* '\"' )
            // InternalRsamlText.g:5121:15: '\"' ( '\\\\' . | ~ ( ( '\\\\' | '\"' ) ) )* '\"'
            {
            match('\"'); 
            // InternalRsamlText.g:5121:19: ( '\\\\' . | ~ ( ( '\\\\' | '\"' ) ) )*
            loop10:
            do {
                int alt10=3;
                int LA10_0 = input.LA(1);

                if ( (LA10_0=='\\') ) {
                    alt10=1;
                }
                else if ( ((LA10_0>='\u0000' && LA10_0<='!')||(LA10_0>='#' && LA10_0<='[')||(LA10_0>=']' && LA10_0<='\uFFFF')) ) {
                    alt10=2;
                }


                switch (alt10) {
            	case 1 :
            	    // InternalRsamlText.g:5121:20: '\\\\' .
            	    {
            	    match('\\'); 
            	    matchAny(); 

            	    }
            	    break;
            	case 2 :
            	    // InternalRsamlText.g:5121:27: ~ ( ( '\\\\' | '\"' ) )
            	    {
            	    if ( (input.LA(1)>='\u0000' && input.LA(1)<='!')||(input.LA(1)>='#' && input.LA(1)<='[')||(input.LA(1)>=']' && input.LA(1)<='\uFFFF') ) {
            	        input.consume();

            	    }
            	    else {
            	        MismatchedSetException mse = new MismatchedSetException(null,input);
            	        recover(mse);
            	        throw mse;}


            	    }
            	    break;

            	default :
            	    break loop10;
                }
            } while (true);

            match('\"'); 

            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "RULE_STRING"

    // $ANTLR start "RULE_ML_COMMENT"
    public final void mRULE_ML_COMMENT() throws RecognitionException {
        try {
            int _type = RULE_ML_COMMENT;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:5123:17: ( '/*' ( options {greedy=false; } : . )* '*/' )
            // InternalRsamlText.g:5123:19: '/*' ( options {greedy=false; } : . )* '*/'
            {
            match("/*"); 

            // InternalRsamlText.g:5123:24: ( options {greedy=false; } : . )*
            loop11:
            do {
                int alt11=2;
                int LA11_0 = input.LA(1);

                if ( (LA11_0=='*') ) {
                    int LA11_1 = input.LA(2);

                    if ( (LA11_1=='/') ) {
                        alt11=2;
                    }
                    else if ( ((LA11_1>='\u0000' && LA11_1<='.')||(LA11_1>='0' && LA11_1<='\uFFFF')) ) {
                        alt11=1;
                    }


                }
                else if ( ((LA11_0>='\u0000' && LA11_0<=')')||(LA11_0>='+' && LA11_0<='\uFFFF')) ) {
                    alt11=1;
                }


                switch (alt11) {
            	case 1 :
            	    // InternalRsamlText.g:5123:52: .
            	    {
            	    matchAny(); 

            	    }
            	    break;

            	default :
            	    break loop11;
                }
            } while (true);

            match("*/"); 


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "RULE_ML_COMMENT"

    // $ANTLR start "RULE_SL_COMMENT"
    public final void mRULE_SL_COMMENT() throws RecognitionException {
        try {
            int _type = RULE_SL_COMMENT;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:5125:17: ( '//' (~ ( ( '\\n' | '\\r' ) ) )* ( ( '\\r' )? '\\n' )? )
            // InternalRsamlText.g:5125:19: '//' (~ ( ( '\\n' | '\\r' ) ) )* ( ( '\\r' )? '\\n' )?
            {
            match("//"); 

            // InternalRsamlText.g:5125:24: (~ ( ( '\\n' | '\\r' ) ) )*
            loop12:
            do {
                int alt12=2;
                int LA12_0 = input.LA(1);

                if ( ((LA12_0>='\u0000' && LA12_0<='\t')||(LA12_0>='\u000B' && LA12_0<='\f')||(LA12_0>='\u000E' && LA12_0<='\uFFFF')) ) {
                    alt12=1;
                }


                switch (alt12) {
            	case 1 :
            	    // InternalRsamlText.g:5125:24: ~ ( ( '\\n' | '\\r' ) )
            	    {
            	    if ( (input.LA(1)>='\u0000' && input.LA(1)<='\t')||(input.LA(1)>='\u000B' && input.LA(1)<='\f')||(input.LA(1)>='\u000E' && input.LA(1)<='\uFFFF') ) {
            	        input.consume();

            	    }
            	    else {
            	        MismatchedSetException mse = new MismatchedSetException(null,input);
            	        recover(mse);
            	        throw mse;}


            	    }
            	    break;

            	default :
            	    break loop12;
                }
            } while (true);

            // InternalRsamlText.g:5125:40: ( ( '\\r' )? '\\n' )?
            int alt14=2;
            int LA14_0 = input.LA(1);

            if ( (LA14_0=='\n'||LA14_0=='\r') ) {
                alt14=1;
            }
            switch (alt14) {
                case 1 :
                    // InternalRsamlText.g:5125:41: ( '\\r' )? '\\n'
                    {
                    // InternalRsamlText.g:5125:41: ( '\\r' )?
                    int alt13=2;
                    int LA13_0 = input.LA(1);

                    if ( (LA13_0=='\r') ) {
                        alt13=1;
                    }
                    switch (alt13) {
                        case 1 :
                            // InternalRsamlText.g:5125:41: '\\r'
                            {
                            match('\r'); 

                            }
                            break;

                    }

                    match('\n'); 

                    }
                    break;

            }


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "RULE_SL_COMMENT"

    // $ANTLR start "RULE_WS"
    public final void mRULE_WS() throws RecognitionException {
        try {
            int _type = RULE_WS;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:5127:9: ( ( ' ' | '\\t' | '\\r' | '\\n' )+ )
            // InternalRsamlText.g:5127:11: ( ' ' | '\\t' | '\\r' | '\\n' )+
            {
            // InternalRsamlText.g:5127:11: ( ' ' | '\\t' | '\\r' | '\\n' )+
            int cnt15=0;
            loop15:
            do {
                int alt15=2;
                int LA15_0 = input.LA(1);

                if ( ((LA15_0>='\t' && LA15_0<='\n')||LA15_0=='\r'||LA15_0==' ') ) {
                    alt15=1;
                }


                switch (alt15) {
            	case 1 :
            	    // InternalRsamlText.g:
            	    {
            	    if ( (input.LA(1)>='\t' && input.LA(1)<='\n')||input.LA(1)=='\r'||input.LA(1)==' ' ) {
            	        input.consume();

            	    }
            	    else {
            	        MismatchedSetException mse = new MismatchedSetException(null,input);
            	        recover(mse);
            	        throw mse;}


            	    }
            	    break;

            	default :
            	    if ( cnt15 >= 1 ) break loop15;
                        EarlyExitException eee =
                            new EarlyExitException(15, input);
                        throw eee;
                }
                cnt15++;
            } while (true);


            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "RULE_WS"

    // $ANTLR start "RULE_ANY_OTHER"
    public final void mRULE_ANY_OTHER() throws RecognitionException {
        try {
            int _type = RULE_ANY_OTHER;
            int _channel = DEFAULT_TOKEN_CHANNEL;
            // InternalRsamlText.g:5129:16: ( . )
            // InternalRsamlText.g:5129:18: .
            {
            matchAny(); 

            }

            state.type = _type;
            state.channel = _channel;
        }
        finally {
        }
    }
    // $ANTLR end "RULE_ANY_OTHER"

    public void mTokens() throws RecognitionException {
        // InternalRsamlText.g:1:8: ( T__11 | T__12 | T__13 | T__14 | T__15 | T__16 | T__17 | T__18 | T__19 | T__20 | T__21 | T__22 | T__23 | T__24 | T__25 | T__26 | T__27 | T__28 | T__29 | T__30 | T__31 | T__32 | T__33 | T__34 | T__35 | T__36 | T__37 | T__38 | T__39 | T__40 | T__41 | T__42 | T__43 | T__44 | T__45 | T__46 | T__47 | T__48 | T__49 | T__50 | T__51 | T__52 | T__53 | T__54 | T__55 | T__56 | T__57 | T__58 | T__59 | T__60 | T__61 | T__62 | T__63 | T__64 | T__65 | T__66 | T__67 | T__68 | T__69 | T__70 | T__71 | T__72 | T__73 | T__74 | T__75 | T__76 | T__77 | T__78 | T__79 | T__80 | T__81 | T__82 | T__83 | T__84 | T__85 | T__86 | T__87 | T__88 | T__89 | T__90 | T__91 | T__92 | T__93 | T__94 | T__95 | T__96 | T__97 | T__98 | T__99 | T__100 | T__101 | T__102 | T__103 | T__104 | T__105 | T__106 | T__107 | T__108 | T__109 | T__110 | T__111 | T__112 | T__113 | T__114 | T__115 | T__116 | T__117 | T__118 | T__119 | RULE_ID | RULE_NUMBER | RULE_STRING | RULE_ML_COMMENT | RULE_SL_COMMENT | RULE_WS | RULE_ANY_OTHER )
        int alt16=116;
        alt16 = dfa16.predict(input);
        switch (alt16) {
            case 1 :
                // InternalRsamlText.g:1:10: T__11
                {
                mT__11(); 

                }
                break;
            case 2 :
                // InternalRsamlText.g:1:16: T__12
                {
                mT__12(); 

                }
                break;
            case 3 :
                // InternalRsamlText.g:1:22: T__13
                {
                mT__13(); 

                }
                break;
            case 4 :
                // InternalRsamlText.g:1:28: T__14
                {
                mT__14(); 

                }
                break;
            case 5 :
                // InternalRsamlText.g:1:34: T__15
                {
                mT__15(); 

                }
                break;
            case 6 :
                // InternalRsamlText.g:1:40: T__16
                {
                mT__16(); 

                }
                break;
            case 7 :
                // InternalRsamlText.g:1:46: T__17
                {
                mT__17(); 

                }
                break;
            case 8 :
                // InternalRsamlText.g:1:52: T__18
                {
                mT__18(); 

                }
                break;
            case 9 :
                // InternalRsamlText.g:1:58: T__19
                {
                mT__19(); 

                }
                break;
            case 10 :
                // InternalRsamlText.g:1:64: T__20
                {
                mT__20(); 

                }
                break;
            case 11 :
                // InternalRsamlText.g:1:70: T__21
                {
                mT__21(); 

                }
                break;
            case 12 :
                // InternalRsamlText.g:1:76: T__22
                {
                mT__22(); 

                }
                break;
            case 13 :
                // InternalRsamlText.g:1:82: T__23
                {
                mT__23(); 

                }
                break;
            case 14 :
                // InternalRsamlText.g:1:88: T__24
                {
                mT__24(); 

                }
                break;
            case 15 :
                // InternalRsamlText.g:1:94: T__25
                {
                mT__25(); 

                }
                break;
            case 16 :
                // InternalRsamlText.g:1:100: T__26
                {
                mT__26(); 

                }
                break;
            case 17 :
                // InternalRsamlText.g:1:106: T__27
                {
                mT__27(); 

                }
                break;
            case 18 :
                // InternalRsamlText.g:1:112: T__28
                {
                mT__28(); 

                }
                break;
            case 19 :
                // InternalRsamlText.g:1:118: T__29
                {
                mT__29(); 

                }
                break;
            case 20 :
                // InternalRsamlText.g:1:124: T__30
                {
                mT__30(); 

                }
                break;
            case 21 :
                // InternalRsamlText.g:1:130: T__31
                {
                mT__31(); 

                }
                break;
            case 22 :
                // InternalRsamlText.g:1:136: T__32
                {
                mT__32(); 

                }
                break;
            case 23 :
                // InternalRsamlText.g:1:142: T__33
                {
                mT__33(); 

                }
                break;
            case 24 :
                // InternalRsamlText.g:1:148: T__34
                {
                mT__34(); 

                }
                break;
            case 25 :
                // InternalRsamlText.g:1:154: T__35
                {
                mT__35(); 

                }
                break;
            case 26 :
                // InternalRsamlText.g:1:160: T__36
                {
                mT__36(); 

                }
                break;
            case 27 :
                // InternalRsamlText.g:1:166: T__37
                {
                mT__37(); 

                }
                break;
            case 28 :
                // InternalRsamlText.g:1:172: T__38
                {
                mT__38(); 

                }
                break;
            case 29 :
                // InternalRsamlText.g:1:178: T__39
                {
                mT__39(); 

                }
                break;
            case 30 :
                // InternalRsamlText.g:1:184: T__40
                {
                mT__40(); 

                }
                break;
            case 31 :
                // InternalRsamlText.g:1:190: T__41
                {
                mT__41(); 

                }
                break;
            case 32 :
                // InternalRsamlText.g:1:196: T__42
                {
                mT__42(); 

                }
                break;
            case 33 :
                // InternalRsamlText.g:1:202: T__43
                {
                mT__43(); 

                }
                break;
            case 34 :
                // InternalRsamlText.g:1:208: T__44
                {
                mT__44(); 

                }
                break;
            case 35 :
                // InternalRsamlText.g:1:214: T__45
                {
                mT__45(); 

                }
                break;
            case 36 :
                // InternalRsamlText.g:1:220: T__46
                {
                mT__46(); 

                }
                break;
            case 37 :
                // InternalRsamlText.g:1:226: T__47
                {
                mT__47(); 

                }
                break;
            case 38 :
                // InternalRsamlText.g:1:232: T__48
                {
                mT__48(); 

                }
                break;
            case 39 :
                // InternalRsamlText.g:1:238: T__49
                {
                mT__49(); 

                }
                break;
            case 40 :
                // InternalRsamlText.g:1:244: T__50
                {
                mT__50(); 

                }
                break;
            case 41 :
                // InternalRsamlText.g:1:250: T__51
                {
                mT__51(); 

                }
                break;
            case 42 :
                // InternalRsamlText.g:1:256: T__52
                {
                mT__52(); 

                }
                break;
            case 43 :
                // InternalRsamlText.g:1:262: T__53
                {
                mT__53(); 

                }
                break;
            case 44 :
                // InternalRsamlText.g:1:268: T__54
                {
                mT__54(); 

                }
                break;
            case 45 :
                // InternalRsamlText.g:1:274: T__55
                {
                mT__55(); 

                }
                break;
            case 46 :
                // InternalRsamlText.g:1:280: T__56
                {
                mT__56(); 

                }
                break;
            case 47 :
                // InternalRsamlText.g:1:286: T__57
                {
                mT__57(); 

                }
                break;
            case 48 :
                // InternalRsamlText.g:1:292: T__58
                {
                mT__58(); 

                }
                break;
            case 49 :
                // InternalRsamlText.g:1:298: T__59
                {
                mT__59(); 

                }
                break;
            case 50 :
                // InternalRsamlText.g:1:304: T__60
                {
                mT__60(); 

                }
                break;
            case 51 :
                // InternalRsamlText.g:1:310: T__61
                {
                mT__61(); 

                }
                break;
            case 52 :
                // InternalRsamlText.g:1:316: T__62
                {
                mT__62(); 

                }
                break;
            case 53 :
                // InternalRsamlText.g:1:322: T__63
                {
                mT__63(); 

                }
                break;
            case 54 :
                // InternalRsamlText.g:1:328: T__64
                {
                mT__64(); 

                }
                break;
            case 55 :
                // InternalRsamlText.g:1:334: T__65
                {
                mT__65(); 

                }
                break;
            case 56 :
                // InternalRsamlText.g:1:340: T__66
                {
                mT__66(); 

                }
                break;
            case 57 :
                // InternalRsamlText.g:1:346: T__67
                {
                mT__67(); 

                }
                break;
            case 58 :
                // InternalRsamlText.g:1:352: T__68
                {
                mT__68(); 

                }
                break;
            case 59 :
                // InternalRsamlText.g:1:358: T__69
                {
                mT__69(); 

                }
                break;
            case 60 :
                // InternalRsamlText.g:1:364: T__70
                {
                mT__70(); 

                }
                break;
            case 61 :
                // InternalRsamlText.g:1:370: T__71
                {
                mT__71(); 

                }
                break;
            case 62 :
                // InternalRsamlText.g:1:376: T__72
                {
                mT__72(); 

                }
                break;
            case 63 :
                // InternalRsamlText.g:1:382: T__73
                {
                mT__73(); 

                }
                break;
            case 64 :
                // InternalRsamlText.g:1:388: T__74
                {
                mT__74(); 

                }
                break;
            case 65 :
                // InternalRsamlText.g:1:394: T__75
                {
                mT__75(); 

                }
                break;
            case 66 :
                // InternalRsamlText.g:1:400: T__76
                {
                mT__76(); 

                }
                break;
            case 67 :
                // InternalRsamlText.g:1:406: T__77
                {
                mT__77(); 

                }
                break;
            case 68 :
                // InternalRsamlText.g:1:412: T__78
                {
                mT__78(); 

                }
                break;
            case 69 :
                // InternalRsamlText.g:1:418: T__79
                {
                mT__79(); 

                }
                break;
            case 70 :
                // InternalRsamlText.g:1:424: T__80
                {
                mT__80(); 

                }
                break;
            case 71 :
                // InternalRsamlText.g:1:430: T__81
                {
                mT__81(); 

                }
                break;
            case 72 :
                // InternalRsamlText.g:1:436: T__82
                {
                mT__82(); 

                }
                break;
            case 73 :
                // InternalRsamlText.g:1:442: T__83
                {
                mT__83(); 

                }
                break;
            case 74 :
                // InternalRsamlText.g:1:448: T__84
                {
                mT__84(); 

                }
                break;
            case 75 :
                // InternalRsamlText.g:1:454: T__85
                {
                mT__85(); 

                }
                break;
            case 76 :
                // InternalRsamlText.g:1:460: T__86
                {
                mT__86(); 

                }
                break;
            case 77 :
                // InternalRsamlText.g:1:466: T__87
                {
                mT__87(); 

                }
                break;
            case 78 :
                // InternalRsamlText.g:1:472: T__88
                {
                mT__88(); 

                }
                break;
            case 79 :
                // InternalRsamlText.g:1:478: T__89
                {
                mT__89(); 

                }
                break;
            case 80 :
                // InternalRsamlText.g:1:484: T__90
                {
                mT__90(); 

                }
                break;
            case 81 :
                // InternalRsamlText.g:1:490: T__91
                {
                mT__91(); 

                }
                break;
            case 82 :
                // InternalRsamlText.g:1:496: T__92
                {
                mT__92(); 

                }
                break;
            case 83 :
                // InternalRsamlText.g:1:502: T__93
                {
                mT__93(); 

                }
                break;
            case 84 :
                // InternalRsamlText.g:1:508: T__94
                {
                mT__94(); 

                }
                break;
            case 85 :
                // InternalRsamlText.g:1:514: T__95
                {
                mT__95(); 

                }
                break;
            case 86 :
                // InternalRsamlText.g:1:520: T__96
                {
                mT__96(); 

                }
                break;
            case 87 :
                // InternalRsamlText.g:1:526: T__97
                {
                mT__97(); 

                }
                break;
            case 88 :
                // InternalRsamlText.g:1:532: T__98
                {
                mT__98(); 

                }
                break;
            case 89 :
                // InternalRsamlText.g:1:538: T__99
                {
                mT__99(); 

                }
                break;
            case 90 :
                // InternalRsamlText.g:1:544: T__100
                {
                mT__100(); 

                }
                break;
            case 91 :
                // InternalRsamlText.g:1:551: T__101
                {
                mT__101(); 

                }
                break;
            case 92 :
                // InternalRsamlText.g:1:558: T__102
                {
                mT__102(); 

                }
                break;
            case 93 :
                // InternalRsamlText.g:1:565: T__103
                {
                mT__103(); 

                }
                break;
            case 94 :
                // InternalRsamlText.g:1:572: T__104
                {
                mT__104(); 

                }
                break;
            case 95 :
                // InternalRsamlText.g:1:579: T__105
                {
                mT__105(); 

                }
                break;
            case 96 :
                // InternalRsamlText.g:1:586: T__106
                {
                mT__106(); 

                }
                break;
            case 97 :
                // InternalRsamlText.g:1:593: T__107
                {
                mT__107(); 

                }
                break;
            case 98 :
                // InternalRsamlText.g:1:600: T__108
                {
                mT__108(); 

                }
                break;
            case 99 :
                // InternalRsamlText.g:1:607: T__109
                {
                mT__109(); 

                }
                break;
            case 100 :
                // InternalRsamlText.g:1:614: T__110
                {
                mT__110(); 

                }
                break;
            case 101 :
                // InternalRsamlText.g:1:621: T__111
                {
                mT__111(); 

                }
                break;
            case 102 :
                // InternalRsamlText.g:1:628: T__112
                {
                mT__112(); 

                }
                break;
            case 103 :
                // InternalRsamlText.g:1:635: T__113
                {
                mT__113(); 

                }
                break;
            case 104 :
                // InternalRsamlText.g:1:642: T__114
                {
                mT__114(); 

                }
                break;
            case 105 :
                // InternalRsamlText.g:1:649: T__115
                {
                mT__115(); 

                }
                break;
            case 106 :
                // InternalRsamlText.g:1:656: T__116
                {
                mT__116(); 

                }
                break;
            case 107 :
                // InternalRsamlText.g:1:663: T__117
                {
                mT__117(); 

                }
                break;
            case 108 :
                // InternalRsamlText.g:1:670: T__118
                {
                mT__118(); 

                }
                break;
            case 109 :
                // InternalRsamlText.g:1:677: T__119
                {
                mT__119(); 

                }
                break;
            case 110 :
                // InternalRsamlText.g:1:684: RULE_ID
                {
                mRULE_ID(); 

                }
                break;
            case 111 :
                // InternalRsamlText.g:1:692: RULE_NUMBER
                {
                mRULE_NUMBER(); 

                }
                break;
            case 112 :
                // InternalRsamlText.g:1:704: RULE_STRING
                {
                mRULE_STRING(); 

                }
                break;
            case 113 :
                // InternalRsamlText.g:1:716: RULE_ML_COMMENT
                {
                mRULE_ML_COMMENT(); 

                }
                break;
            case 114 :
                // InternalRsamlText.g:1:732: RULE_SL_COMMENT
                {
                mRULE_SL_COMMENT(); 

                }
                break;
            case 115 :
                // InternalRsamlText.g:1:748: RULE_WS
                {
                mRULE_WS(); 

                }
                break;
            case 116 :
                // InternalRsamlText.g:1:756: RULE_ANY_OTHER
                {
                mRULE_ANY_OTHER(); 

                }
                break;

        }

    }


    protected DFA16 dfa16 = new DFA16(this);
    static final String DFA16_eotS =
        "\1\uffff\1\60\1\uffff\4\60\1\uffff\5\60\1\124\1\uffff\4\60\1\140\4\60\1\uffff\13\60\1\52\2\uffff\2\52\2\uffff\5\60\2\uffff\15\60\1\uffff\1\60\1\u0097\1\60\1\u009a\10\60\1\u00a4\7\60\2\uffff\11\60\3\uffff\7\60\1\uffff\2\60\1\u00c3\3\60\1\u00c7\1\u00c8\1\u00c9\5\60\4\uffff\33\60\1\uffff\2\60\1\uffff\11\60\1\uffff\33\60\1\u0117\2\60\1\uffff\2\60\1\u011c\3\uffff\1\u011d\1\u011e\1\60\1\u0120\12\60\1\u012c\21\60\1\u0141\1\60\1\u0143\1\60\1\u0145\4\60\1\u014a\21\60\1\u015c\13\60\1\u0169\1\60\1\u016b\1\u016c\2\60\1\uffff\3\60\1\u0172\3\uffff\1\60\1\uffff\13\60\1\uffff\12\60\1\u0189\1\60\1\u018b\6\60\1\u0192\1\uffff\1\u0193\1\uffff\1\60\1\uffff\1\u0195\3\60\1\uffff\11\60\1\u01a2\7\60\1\uffff\1\u01ab\1\60\1\u01ad\6\60\1\u01b4\2\60\1\uffff\1\60\2\uffff\5\60\1\uffff\1\u01bd\3\60\1\u01c2\21\60\1\uffff\1\60\1\uffff\1\60\1\u01d7\4\60\2\uffff\1\u01dc\1\uffff\1\60\1\u01de\4\60\1\u01e4\2\60\1\u01e8\2\60\1\uffff\3\60\1\u01ee\1\u01ef\3\60\1\uffff\1\u01f3\1\uffff\6\60\1\uffff\1\60\1\u01fb\2\60\1\u01fe\3\60\1\uffff\3\60\1\u0205\1\uffff\6\60\1\u020c\6\60\1\u0213\3\60\1\u0217\2\60\1\uffff\4\60\1\uffff\1\u021e\1\uffff\3\60\1\u0222\1\u0223\1\uffff\1\60\1\u0225\1\u0226\1\uffff\5\60\2\uffff\3\60\1\uffff\7\60\1\uffff\2\60\1\uffff\1\60\1\u023a\1\u023b\2\60\1\u023f\1\uffff\1\u0240\1\u0241\3\60\1\u0245\1\uffff\3\60\1\u0249\1\u024a\1\u024b\1\uffff\1\u024c\2\60\1\uffff\1\u024f\1\u0250\1\u0251\1\60\1\u0253\1\60\1\uffff\1\u0255\2\60\2\uffff\1\60\2\uffff\6\60\1\u025f\1\u0260\1\60\1\u0262\1\60\1\u0264\1\60\1\u0266\1\u0267\4\60\2\uffff\1\u026c\1\60\1\u026e\3\uffff\1\u026f\2\60\1\uffff\3\60\4\uffff\1\u0275\1\60\3\uffff\1\60\1\uffff\1\u0278\1\uffff\11\60\2\uffff\1\60\1\uffff\1\60\1\uffff\1\60\2\uffff\1\u0285\1\u0286\2\60\1\uffff\1\60\2\uffff\5\60\1\uffff\2\60\1\uffff\1\60\1\u0292\4\60\1\u0297\1\u0298\1\u0299\1\60\1\u029b\1\60\2\uffff\1\60\1\u029e\3\60\1\u02a2\1\60\1\u02a4\1\u02a5\1\60\1\u02a7\1\uffff\1\u02a8\1\u02a9\1\u02aa\1\u02ab\3\uffff\1\u02ac\1\uffff\2\60\1\uffff\1\u02af\1\u02b0\1\u02b1\1\uffff\1\60\2\uffff\1\u02b3\6\uffff\1\u02b4\1\u02b5\3\uffff\1\60\3\uffff\1\u02b7\1\uffff";
    static final String DFA16_eofS =
        "\u02b8\uffff";
    static final String DFA16_minS =
        "\1\0\1\143\1\uffff\4\141\1\uffff\1\156\1\141\1\170\1\143\1\141\1\60\1\uffff\2\162\1\145\1\156\1\60\1\151\1\157\2\151\1\uffff\1\145\1\163\1\111\1\112\2\115\1\104\1\114\1\124\1\141\1\156\1\101\2\uffff\1\0\1\52\2\uffff\1\143\1\150\1\145\1\171\1\160\2\uffff\1\164\2\156\1\141\1\164\1\162\1\146\1\164\1\166\1\143\1\162\1\151\1\141\1\uffff\1\151\1\60\1\160\1\60\1\151\1\162\2\145\1\156\1\144\2\163\1\60\2\156\1\150\1\141\1\160\1\155\1\157\2\uffff\1\156\1\157\1\150\1\164\1\144\1\101\1\141\1\150\1\163\3\uffff\1\156\1\157\1\141\1\163\1\145\1\142\1\141\1\uffff\1\150\1\157\1\60\1\155\2\106\3\60\2\106\1\110\1\116\1\146\4\uffff\1\150\2\151\1\162\1\156\1\150\1\145\1\156\1\145\1\164\1\154\1\143\1\144\2\141\1\145\1\153\3\145\1\153\1\114\1\157\1\143\1\151\1\164\1\144\1\uffff\1\145\1\151\1\uffff\2\147\1\143\1\164\1\105\1\141\1\165\2\163\1\uffff\1\163\1\143\1\145\1\162\1\165\1\145\1\160\1\147\1\162\1\143\1\155\1\145\1\160\1\145\2\143\1\145\2\165\1\151\1\165\1\144\1\167\1\154\1\164\2\162\1\60\1\141\1\154\1\uffff\1\145\1\117\1\60\3\uffff\2\60\1\105\1\60\2\151\1\141\1\157\1\145\1\151\1\143\1\141\1\147\1\145\1\60\1\162\1\141\1\162\1\154\1\101\1\164\1\143\1\114\1\162\1\156\1\154\1\141\1\157\1\141\2\162\1\145\1\60\1\156\1\60\1\102\1\60\1\143\1\147\1\145\1\124\1\60\1\170\1\141\1\147\1\154\1\141\1\151\1\157\1\150\1\144\1\164\1\143\2\162\2\154\1\141\1\164\1\60\1\162\1\165\1\162\1\164\1\124\1\164\1\151\1\145\1\164\1\142\1\145\1\60\1\154\2\60\1\141\1\151\1\uffff\1\166\1\145\1\162\1\60\3\uffff\1\122\1\uffff\1\156\2\164\1\156\1\151\1\166\1\157\1\150\1\156\1\157\1\143\1\uffff\1\141\1\162\2\151\1\171\1\141\1\147\1\151\1\171\1\141\1\60\1\143\1\60\1\147\1\144\1\171\1\157\1\151\1\163\1\60\1\uffff\1\60\1\uffff\1\171\1\uffff\1\60\1\145\1\164\1\171\1\uffff\1\145\1\164\2\145\1\147\1\157\2\162\1\120\1\60\1\164\1\145\1\166\2\145\1\144\1\151\1\uffff\1\60\1\164\1\60\1\151\1\163\2\151\1\166\1\163\1\60\1\151\1\162\1\uffff\1\145\2\uffff\1\162\1\144\1\151\1\141\1\151\1\uffff\1\60\1\151\1\145\1\157\1\60\1\164\1\145\1\144\1\162\1\165\1\162\1\164\1\154\1\145\1\160\1\156\1\160\1\163\1\145\1\157\1\143\1\164\1\uffff\1\171\1\uffff\1\145\1\60\1\145\1\143\1\164\1\163\2\uffff\1\60\1\uffff\1\162\1\60\1\160\1\143\1\145\1\144\1\60\1\145\1\156\1\60\2\157\1\uffff\1\165\1\163\1\151\2\60\1\151\2\157\1\uffff\1\60\1\uffff\1\157\1\145\1\155\1\157\1\145\1\164\1\uffff\1\164\1\60\1\144\1\143\1\60\1\157\1\156\1\143\1\uffff\1\164\1\143\1\162\1\60\1\uffff\1\171\1\163\1\151\1\157\1\155\1\171\1\60\1\151\1\144\1\164\3\145\1\60\1\156\1\154\1\145\1\60\1\163\1\143\1\uffff\1\162\1\145\1\171\1\157\1\uffff\1\60\1\uffff\1\145\1\124\1\156\2\60\1\uffff\1\124\2\60\1\uffff\1\124\1\154\1\162\2\163\2\uffff\1\143\1\156\1\154\1\uffff\1\156\1\144\1\145\1\156\1\162\1\163\1\157\1\uffff\1\147\1\150\1\uffff\1\162\2\60\1\171\1\164\1\60\1\uffff\2\60\1\143\1\156\1\145\1\60\1\uffff\1\172\1\114\1\151\3\60\1\uffff\1\60\1\145\1\156\1\uffff\3\60\1\163\1\60\1\162\1\uffff\1\60\1\151\1\143\2\uffff\1\171\2\uffff\1\171\1\157\1\151\1\145\2\157\2\60\1\151\1\60\1\102\1\60\1\124\2\60\1\162\1\145\1\151\1\141\2\uffff\1\60\1\165\1\60\3\uffff\1\60\1\157\1\162\1\uffff\1\145\1\141\1\157\4\uffff\1\60\1\143\3\uffff\1\163\1\uffff\1\60\1\uffff\1\155\1\171\2\160\1\165\1\143\1\144\2\162\2\uffff\1\143\1\uffff\1\171\1\uffff\1\151\2\uffff\2\60\1\143\1\154\1\uffff\1\162\2\uffff\1\165\1\151\1\144\1\171\1\156\1\uffff\1\171\1\157\1\uffff\1\145\1\60\2\145\1\163\1\171\3\60\1\171\1\60\1\155\2\uffff\1\141\1\60\1\145\1\163\1\143\1\60\1\145\2\60\1\162\1\60\1\uffff\4\60\3\uffff\1\60\1\uffff\1\145\1\154\1\uffff\3\60\1\uffff\1\162\2\uffff\1\60\6\uffff\2\60\3\uffff\1\163\3\uffff\1\60\1\uffff";
    static final String DFA16_maxS =
        "\1\uffff\1\163\1\uffff\1\157\1\165\1\151\1\162\1\uffff\1\163\1\171\1\170\1\143\1\163\1\172\1\uffff\2\165\1\164\1\163\1\76\1\156\1\157\1\171\1\151\1\uffff\1\157\1\165\1\111\1\112\1\122\1\115\1\104\1\114\1\124\1\141\1\156\1\172\2\uffff\1\uffff\1\57\2\uffff\1\143\1\164\1\145\1\171\1\160\2\uffff\1\164\1\162\1\156\1\163\1\164\1\162\1\156\1\171\1\166\1\143\1\162\1\157\1\141\1\uffff\1\151\1\172\1\160\1\172\1\151\1\162\2\145\1\170\1\144\2\163\1\172\2\156\1\150\1\162\1\160\1\156\1\157\2\uffff\1\156\1\157\1\150\1\164\1\144\1\101\1\161\1\160\1\163\3\uffff\1\156\1\157\1\141\1\163\1\145\1\142\1\141\1\uffff\1\150\1\157\1\172\1\155\2\106\3\172\2\106\1\110\1\116\1\146\4\uffff\1\150\1\165\1\151\1\162\1\156\1\150\1\145\1\156\1\145\1\164\1\154\1\143\1\144\2\141\1\145\1\153\3\145\1\153\1\151\1\157\1\143\1\156\1\164\1\144\1\uffff\1\145\1\151\1\uffff\2\147\1\143\1\164\1\114\1\141\1\165\2\163\1\uffff\1\163\1\143\1\145\1\162\1\165\2\160\1\147\1\162\1\143\1\155\1\145\1\160\1\145\1\143\1\154\1\145\2\165\1\151\1\165\1\144\1\167\1\154\1\164\2\162\1\172\1\141\1\154\1\uffff\1\145\1\117\1\172\3\uffff\2\172\1\105\1\172\2\151\1\141\1\166\1\145\1\151\1\143\1\141\1\147\1\145\1\172\1\162\1\141\1\162\1\154\1\142\1\164\1\143\1\114\1\162\1\156\1\154\1\141\1\157\1\141\2\162\1\145\1\172\1\156\1\172\1\102\1\172\1\143\1\147\1\145\1\124\1\172\1\170\1\141\1\147\1\154\1\141\1\151\1\157\1\150\1\144\1\164\1\143\2\162\2\154\1\141\1\164\1\172\1\162\1\165\1\162\1\164\1\151\1\164\1\151\1\145\1\164\1\142\1\145\1\172\1\154\2\172\1\141\1\151\1\uffff\1\166\1\145\1\162\1\172\3\uffff\1\122\1\uffff\1\156\2\164\1\156\1\151\1\166\1\157\1\150\1\156\1\157\1\143\1\uffff\1\141\1\162\2\151\1\171\1\141\1\147\1\151\1\171\1\141\1\172\1\143\1\172\1\147\1\144\1\171\1\157\1\151\1\163\1\172\1\uffff\1\172\1\uffff\1\171\1\uffff\1\172\1\145\1\164\1\171\1\uffff\1\145\1\164\2\145\1\147\1\157\2\162\1\120\1\172\1\164\1\145\1\166\2\145\1\144\1\151\1\uffff\1\172\1\164\1\172\1\151\1\163\2\151\1\166\1\163\1\172\1\151\1\162\1\uffff\1\145\2\uffff\1\162\1\144\1\151\1\141\1\151\1\uffff\1\172\1\151\1\145\1\157\1\172\1\164\1\145\1\144\1\162\1\165\1\162\1\164\1\154\1\145\1\160\1\156\1\160\1\163\1\145\1\157\1\143\1\164\1\uffff\1\171\1\uffff\1\145\1\172\1\145\1\143\1\164\1\163\2\uffff\1\172\1\uffff\1\162\1\172\1\160\1\143\1\145\1\144\1\172\1\145\1\156\1\172\2\157\1\uffff\1\165\1\163\1\151\2\172\1\151\2\157\1\uffff\1\172\1\uffff\1\157\1\145\1\155\1\157\1\145\1\164\1\uffff\1\164\1\172\1\144\1\143\1\172\1\157\1\156\1\143\1\uffff\1\164\1\143\1\162\1\172\1\uffff\1\171\1\163\1\151\1\157\1\155\1\171\1\172\1\151\1\144\1\164\3\145\1\172\1\156\1\154\1\145\1\172\1\163\1\143\1\uffff\1\162\1\145\1\171\1\157\1\uffff\1\172\1\uffff\1\145\1\124\1\156\2\172\1\uffff\1\124\2\172\1\uffff\1\156\1\154\1\162\2\163\2\uffff\1\143\1\156\1\154\1\uffff\1\156\1\144\1\145\1\156\1\162\1\163\1\157\1\uffff\1\147\1\150\1\uffff\1\162\2\172\1\171\1\164\1\172\1\uffff\2\172\1\143\1\156\1\145\1\172\1\uffff\1\172\1\114\1\151\3\172\1\uffff\1\172\1\145\1\156\1\uffff\3\172\1\163\1\172\1\162\1\uffff\1\172\1\151\1\143\2\uffff\1\171\2\uffff\1\171\1\157\1\151\1\145\2\157\2\172\1\151\1\172\1\102\1\172\1\124\2\172\1\162\1\145\1\151\1\141\2\uffff\1\172\1\165\1\172\3\uffff\1\172\1\157\1\162\1\uffff\1\145\1\141\1\157\4\uffff\1\172\1\143\3\uffff\1\163\1\uffff\1\172\1\uffff\1\155\1\171\2\160\1\165\1\143\1\144\2\162\2\uffff\1\143\1\uffff\1\171\1\uffff\1\151\2\uffff\2\172\1\143\1\154\1\uffff\1\162\2\uffff\1\165\1\151\1\144\1\171\1\156\1\uffff\1\171\1\157\1\uffff\1\145\1\172\2\145\1\163\1\171\3\172\1\171\1\172\1\155\2\uffff\1\141\1\172\1\145\1\163\1\143\1\172\1\145\2\172\1\162\1\172\1\uffff\4\172\3\uffff\1\172\1\uffff\1\145\1\154\1\uffff\3\172\1\uffff\1\162\2\uffff\1\172\6\uffff\2\172\3\uffff\1\163\3\uffff\1\172\1\uffff";
    static final String DFA16_acceptS =
        "\2\uffff\1\2\4\uffff\1\7\6\uffff\1\24\11\uffff\1\107\14\uffff\1\156\1\157\2\uffff\1\163\1\164\5\uffff\1\156\1\2\15\uffff\1\7\24\uffff\1\125\1\24\11\uffff\1\43\1\155\1\157\7\uffff\1\107\16\uffff\1\160\1\161\1\162\1\163\33\uffff\1\123\2\uffff\1\104\11\uffff\1\124\36\uffff\1\122\3\uffff\1\132\1\133\1\134\115\uffff\1\105\4\uffff\1\131\1\135\1\136\1\uffff\1\153\13\uffff\1\76\24\uffff\1\57\1\uffff\1\11\1\uffff\1\12\4\uffff\1\16\21\uffff\1\103\14\uffff\1\52\1\uffff\1\55\1\77\5\uffff\1\130\26\uffff\1\17\1\uffff\1\20\6\uffff\1\64\1\146\1\uffff\1\41\14\uffff\1\34\10\uffff\1\114\1\uffff\1\66\6\uffff\1\35\10\uffff\1\137\4\uffff\1\32\24\uffff\1\14\4\uffff\1\74\1\uffff\1\46\5\uffff\1\22\3\uffff\1\51\5\uffff\1\115\1\150\3\uffff\1\36\7\uffff\1\67\2\uffff\1\113\6\uffff\1\62\6\uffff\1\42\6\uffff\1\145\3\uffff\1\102\6\uffff\1\45\3\uffff\1\147\1\101\1\uffff\1\54\1\23\23\uffff\1\142\1\140\3\uffff\1\53\1\61\1\60\3\uffff\1\3\3\uffff\1\15\1\37\1\72\1\47\2\uffff\1\6\1\117\1\151\1\uffff\1\56\1\uffff\1\13\11\uffff\1\120\1\26\1\uffff\1\33\1\uffff\1\116\1\uffff\1\70\1\71\4\uffff\1\154\1\uffff\1\25\1\121\5\uffff\1\5\2\uffff\1\75\14\uffff\1\44\1\73\13\uffff\1\106\4\uffff\1\143\1\50\1\63\1\uffff\1\65\2\uffff\1\112\3\uffff\1\110\1\uffff\1\10\1\100\1\uffff\1\21\1\40\1\27\1\126\1\30\1\31\2\uffff\1\1\1\127\1\141\1\uffff\1\152\1\144\1\111\1\uffff\1\4";
    static final String DFA16_specialS =
        "\1\0\46\uffff\1\1\u0290\uffff}>";
    static final String[] DFA16_transitionS = {
            "\11\52\2\51\2\52\1\51\22\52\1\51\1\52\1\47\11\52\1\16\1\23\1\30\1\50\12\46\7\52\3\45\1\36\1\37\1\33\2\45\1\43\2\45\1\40\1\45\1\42\1\41\2\45\1\35\1\34\7\45\3\52\1\44\1\45\1\52\1\1\1\31\1\3\1\4\1\12\1\17\1\25\1\26\1\22\1\45\1\24\1\5\1\14\1\32\1\20\1\6\1\45\1\21\1\15\1\11\1\10\1\27\1\13\3\45\1\2\1\52\1\7\uff82\52",
            "\1\54\10\uffff\1\57\3\uffff\1\55\1\uffff\1\53\1\56",
            "",
            "\1\62\3\uffff\1\64\11\uffff\1\63",
            "\1\66\3\uffff\1\65\17\uffff\1\67",
            "\1\71\3\uffff\1\72\3\uffff\1\70",
            "\1\73\3\uffff\1\74\6\uffff\1\76\5\uffff\1\75",
            "",
            "\1\100\4\uffff\1\101",
            "\1\105\15\uffff\1\103\2\uffff\1\104\6\uffff\1\102",
            "\1\106",
            "\1\107",
            "\1\110\3\uffff\1\112\3\uffff\1\113\5\uffff\1\111\3\uffff\1\114",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\2\60\1\117\1\60\1\115\3\60\1\122\6\60\1\123\3\60\1\120\1\121\3\60\1\116\1\60",
            "",
            "\1\127\2\uffff\1\126",
            "\1\132\1\uffff\1\130\1\131",
            "\1\134\16\uffff\1\133",
            "\1\135\4\uffff\1\136",
            "\12\141\4\uffff\1\137",
            "\1\142\4\uffff\1\143",
            "\1\144",
            "\1\146\5\uffff\1\145\11\uffff\1\147",
            "\1\150",
            "",
            "\1\152\11\uffff\1\153",
            "\1\154\1\uffff\1\155",
            "\1\156",
            "\1\157",
            "\1\161\4\uffff\1\160",
            "\1\162",
            "\1\163",
            "\1\164",
            "\1\165",
            "\1\166",
            "\1\167",
            "\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "",
            "\0\170",
            "\1\171\4\uffff\1\172",
            "",
            "",
            "\1\174",
            "\1\176\13\uffff\1\175",
            "\1\177",
            "\1\u0080",
            "\1\u0081",
            "",
            "",
            "\1\u0082",
            "\1\u0083\3\uffff\1\u0084",
            "\1\u0085",
            "\1\u0088\1\uffff\1\u0086\17\uffff\1\u0087",
            "\1\u0089",
            "\1\u008a",
            "\1\u008b\7\uffff\1\u008c",
            "\1\u008e\4\uffff\1\u008d",
            "\1\u008f",
            "\1\u0090",
            "\1\u0091",
            "\1\u0092\5\uffff\1\u0093",
            "\1\u0094",
            "",
            "\1\u0095",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\4\60\1\u0096\25\60",
            "\1\u0098",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\17\60\1\u0099\12\60",
            "\1\u009b",
            "\1\u009c",
            "\1\u009d",
            "\1\u009e",
            "\1\u00a0\11\uffff\1\u009f",
            "\1\u00a1",
            "\1\u00a2",
            "\1\u00a3",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u00a5",
            "\1\u00a6",
            "\1\u00a7",
            "\1\u00a8\20\uffff\1\u00a9",
            "\1\u00aa",
            "\1\u00ab\1\u00ac",
            "\1\u00ad",
            "",
            "",
            "\1\u00ae",
            "\1\u00af",
            "\1\u00b0",
            "\1\u00b1",
            "\1\u00b2",
            "\1\u00b3",
            "\1\u00b4\1\uffff\1\u00b5\15\uffff\1\u00b6",
            "\1\u00b8\7\uffff\1\u00b7",
            "\1\u00b9",
            "",
            "",
            "",
            "\1\u00ba",
            "\1\u00bb",
            "\1\u00bc",
            "\1\u00bd",
            "\1\u00be",
            "\1\u00bf",
            "\1\u00c0",
            "",
            "\1\u00c1",
            "\1\u00c2",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u00c4",
            "\1\u00c5",
            "\1\u00c6",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u00ca",
            "\1\u00cb",
            "\1\u00cc",
            "\1\u00cd",
            "\1\u00ce",
            "",
            "",
            "",
            "",
            "\1\u00cf",
            "\1\u00d1\13\uffff\1\u00d0",
            "\1\u00d2",
            "\1\u00d3",
            "\1\u00d4",
            "\1\u00d5",
            "\1\u00d6",
            "\1\u00d7",
            "\1\u00d8",
            "\1\u00d9",
            "\1\u00da",
            "\1\u00db",
            "\1\u00dc",
            "\1\u00dd",
            "\1\u00de",
            "\1\u00df",
            "\1\u00e0",
            "\1\u00e1",
            "\1\u00e2",
            "\1\u00e3",
            "\1\u00e4",
            "\1\u00e6\3\uffff\1\u00e7\30\uffff\1\u00e5",
            "\1\u00e8",
            "\1\u00e9",
            "\1\u00eb\4\uffff\1\u00ea",
            "\1\u00ec",
            "\1\u00ed",
            "",
            "\1\u00ee",
            "\1\u00ef",
            "",
            "\1\u00f0",
            "\1\u00f1",
            "\1\u00f2",
            "\1\u00f3",
            "\1\u00f4\6\uffff\1\u00f5",
            "\1\u00f6",
            "\1\u00f7",
            "\1\u00f8",
            "\1\u00f9",
            "",
            "\1\u00fa",
            "\1\u00fb",
            "\1\u00fc",
            "\1\u00fd",
            "\1\u00fe",
            "\1\u0100\12\uffff\1\u00ff",
            "\1\u0101",
            "\1\u0102",
            "\1\u0103",
            "\1\u0104",
            "\1\u0105",
            "\1\u0106",
            "\1\u0107",
            "\1\u0108",
            "\1\u0109",
            "\1\u010b\10\uffff\1\u010a",
            "\1\u010c",
            "\1\u010d",
            "\1\u010e",
            "\1\u010f",
            "\1\u0110",
            "\1\u0111",
            "\1\u0112",
            "\1\u0113",
            "\1\u0114",
            "\1\u0115",
            "\1\u0116",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0118",
            "\1\u0119",
            "",
            "\1\u011a",
            "\1\u011b",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u011f",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0121",
            "\1\u0122",
            "\1\u0123",
            "\1\u0124\6\uffff\1\u0125",
            "\1\u0126",
            "\1\u0127",
            "\1\u0128",
            "\1\u0129",
            "\1\u012a",
            "\1\u012b",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u012d",
            "\1\u012e",
            "\1\u012f",
            "\1\u0130",
            "\1\u0133\22\uffff\1\u0131\15\uffff\1\u0132",
            "\1\u0134",
            "\1\u0135",
            "\1\u0136",
            "\1\u0137",
            "\1\u0138",
            "\1\u0139",
            "\1\u013a",
            "\1\u013b",
            "\1\u013c",
            "\1\u013d",
            "\1\u013e",
            "\1\u013f",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\22\60\1\u0140\7\60",
            "\1\u0142",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0144",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0146",
            "\1\u0147",
            "\1\u0148",
            "\1\u0149",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u014b",
            "\1\u014c",
            "\1\u014d",
            "\1\u014e",
            "\1\u014f",
            "\1\u0150",
            "\1\u0151",
            "\1\u0152",
            "\1\u0153",
            "\1\u0154",
            "\1\u0155",
            "\1\u0156",
            "\1\u0157",
            "\1\u0158",
            "\1\u0159",
            "\1\u015a",
            "\1\u015b",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u015d",
            "\1\u015e",
            "\1\u015f",
            "\1\u0160",
            "\1\u0162\24\uffff\1\u0161",
            "\1\u0163",
            "\1\u0164",
            "\1\u0165",
            "\1\u0166",
            "\1\u0167",
            "\1\u0168",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u016a",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u016d",
            "\1\u016e",
            "",
            "\1\u016f",
            "\1\u0170",
            "\1\u0171",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "",
            "",
            "\1\u0173",
            "",
            "\1\u0174",
            "\1\u0175",
            "\1\u0176",
            "\1\u0177",
            "\1\u0178",
            "\1\u0179",
            "\1\u017a",
            "\1\u017b",
            "\1\u017c",
            "\1\u017d",
            "\1\u017e",
            "",
            "\1\u017f",
            "\1\u0180",
            "\1\u0181",
            "\1\u0182",
            "\1\u0183",
            "\1\u0184",
            "\1\u0185",
            "\1\u0186",
            "\1\u0187",
            "\1\u0188",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u018a",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u018c",
            "\1\u018d",
            "\1\u018e",
            "\1\u018f",
            "\1\u0190",
            "\1\u0191",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\1\u0194",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0196",
            "\1\u0197",
            "\1\u0198",
            "",
            "\1\u0199",
            "\1\u019a",
            "\1\u019b",
            "\1\u019c",
            "\1\u019d",
            "\1\u019e",
            "\1\u019f",
            "\1\u01a0",
            "\1\u01a1",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u01a3",
            "\1\u01a4",
            "\1\u01a5",
            "\1\u01a6",
            "\1\u01a7",
            "\1\u01a8",
            "\1\u01a9",
            "",
            "\12\60\7\uffff\17\60\1\u01aa\12\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u01ac",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u01ae",
            "\1\u01af",
            "\1\u01b0",
            "\1\u01b1",
            "\1\u01b2",
            "\1\u01b3",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u01b5",
            "\1\u01b6",
            "",
            "\1\u01b7",
            "",
            "",
            "\1\u01b8",
            "\1\u01b9",
            "\1\u01ba",
            "\1\u01bb",
            "\1\u01bc",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u01be",
            "\1\u01bf",
            "\1\u01c0",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\22\60\1\u01c1\7\60",
            "\1\u01c3",
            "\1\u01c4",
            "\1\u01c5",
            "\1\u01c6",
            "\1\u01c7",
            "\1\u01c8",
            "\1\u01c9",
            "\1\u01ca",
            "\1\u01cb",
            "\1\u01cc",
            "\1\u01cd",
            "\1\u01ce",
            "\1\u01cf",
            "\1\u01d0",
            "\1\u01d1",
            "\1\u01d2",
            "\1\u01d3",
            "",
            "\1\u01d4",
            "",
            "\1\u01d5",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\10\60\1\u01d6\21\60",
            "\1\u01d8",
            "\1\u01d9",
            "\1\u01da",
            "\1\u01db",
            "",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\1\u01dd",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u01df",
            "\1\u01e0",
            "\1\u01e1",
            "\1\u01e2",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\22\60\1\u01e3\7\60",
            "\1\u01e5",
            "\1\u01e6",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\22\60\1\u01e7\7\60",
            "\1\u01e9",
            "\1\u01ea",
            "",
            "\1\u01eb",
            "\1\u01ec",
            "\1\u01ed",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u01f0",
            "\1\u01f1",
            "\1\u01f2",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\1\u01f4",
            "\1\u01f5",
            "\1\u01f6",
            "\1\u01f7",
            "\1\u01f8",
            "\1\u01f9",
            "",
            "\1\u01fa",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u01fc",
            "\1\u01fd",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u01ff",
            "\1\u0200",
            "\1\u0201",
            "",
            "\1\u0202",
            "\1\u0203",
            "\1\u0204",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\1\u0206",
            "\1\u0207",
            "\1\u0208",
            "\1\u0209",
            "\1\u020a",
            "\1\u020b",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u020d",
            "\1\u020e",
            "\1\u020f",
            "\1\u0210",
            "\1\u0211",
            "\1\u0212",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0214",
            "\1\u0215",
            "\1\u0216",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0218",
            "\1\u0219",
            "",
            "\1\u021a",
            "\1\u021b",
            "\1\u021c",
            "\1\u021d",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\1\u021f",
            "\1\u0220",
            "\1\u0221",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\1\u0224",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\1\u0227\31\uffff\1\u0228",
            "\1\u0229",
            "\1\u022a",
            "\1\u022b",
            "\1\u022c",
            "",
            "",
            "\1\u022d",
            "\1\u022e",
            "\1\u022f",
            "",
            "\1\u0230",
            "\1\u0231",
            "\1\u0232",
            "\1\u0233",
            "\1\u0234",
            "\1\u0235",
            "\1\u0236",
            "",
            "\1\u0237",
            "\1\u0238",
            "",
            "\1\u0239",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u023c",
            "\1\u023d",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\22\60\1\u023e\7\60",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0242",
            "\1\u0243",
            "\1\u0244",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\1\u0246",
            "\1\u0247",
            "\1\u0248",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u024d",
            "\1\u024e",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0252",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0254",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0256",
            "\1\u0257",
            "",
            "",
            "\1\u0258",
            "",
            "",
            "\1\u0259",
            "\1\u025a",
            "\1\u025b",
            "\1\u025c",
            "\1\u025d",
            "\1\u025e",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0261",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0263",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0265",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0268",
            "\1\u0269",
            "\1\u026a",
            "\1\u026b",
            "",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u026d",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0270",
            "\1\u0271",
            "",
            "\1\u0272",
            "\1\u0273",
            "\1\u0274",
            "",
            "",
            "",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0276",
            "",
            "",
            "",
            "\1\u0277",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\1\u0279",
            "\1\u027a",
            "\1\u027b",
            "\1\u027c",
            "\1\u027d",
            "\1\u027e",
            "\1\u027f",
            "\1\u0280",
            "\1\u0281",
            "",
            "",
            "\1\u0282",
            "",
            "\1\u0283",
            "",
            "\1\u0284",
            "",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0287",
            "\1\u0288",
            "",
            "\1\u0289",
            "",
            "",
            "\1\u028a",
            "\1\u028b",
            "\1\u028c",
            "\1\u028d",
            "\1\u028e",
            "",
            "\1\u028f",
            "\1\u0290",
            "",
            "\1\u0291",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u0293",
            "\1\u0294",
            "\1\u0295",
            "\1\u0296",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u029a",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u029c",
            "",
            "",
            "\1\u029d",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u029f",
            "\1\u02a0",
            "\1\u02a1",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u02a3",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\1\u02a6",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\1\u02ad",
            "\1\u02ae",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "\1\u02b2",
            "",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "",
            "",
            "",
            "",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            "",
            "",
            "",
            "\1\u02b6",
            "",
            "",
            "",
            "\12\60\7\uffff\32\60\4\uffff\1\60\1\uffff\32\60",
            ""
    };

    static final short[] DFA16_eot = DFA.unpackEncodedString(DFA16_eotS);
    static final short[] DFA16_eof = DFA.unpackEncodedString(DFA16_eofS);
    static final char[] DFA16_min = DFA.unpackEncodedStringToUnsignedChars(DFA16_minS);
    static final char[] DFA16_max = DFA.unpackEncodedStringToUnsignedChars(DFA16_maxS);
    static final short[] DFA16_accept = DFA.unpackEncodedString(DFA16_acceptS);
    static final short[] DFA16_special = DFA.unpackEncodedString(DFA16_specialS);
    static final short[][] DFA16_transition;

    static {
        int numStates = DFA16_transitionS.length;
        DFA16_transition = new short[numStates][];
        for (int i=0; i<numStates; i++) {
            DFA16_transition[i] = DFA.unpackEncodedString(DFA16_transitionS[i]);
        }
    }

    class DFA16 extends DFA {

        public DFA16(BaseRecognizer recognizer) {
            this.recognizer = recognizer;
            this.decisionNumber = 16;
            this.eot = DFA16_eot;
            this.eof = DFA16_eof;
            this.min = DFA16_min;
            this.max = DFA16_max;
            this.accept = DFA16_accept;
            this.special = DFA16_special;
            this.transition = DFA16_transition;
        }
        public String getDescription() {
            return "1:1: Tokens : ( T__11 | T__12 | T__13 | T__14 | T__15 | T__16 | T__17 | T__18 | T__19 | T__20 | T__21 | T__22 | T__23 | T__24 | T__25 | T__26 | T__27 | T__28 | T__29 | T__30 | T__31 | T__32 | T__33 | T__34 | T__35 | T__36 | T__37 | T__38 | T__39 | T__40 | T__41 | T__42 | T__43 | T__44 | T__45 | T__46 | T__47 | T__48 | T__49 | T__50 | T__51 | T__52 | T__53 | T__54 | T__55 | T__56 | T__57 | T__58 | T__59 | T__60 | T__61 | T__62 | T__63 | T__64 | T__65 | T__66 | T__67 | T__68 | T__69 | T__70 | T__71 | T__72 | T__73 | T__74 | T__75 | T__76 | T__77 | T__78 | T__79 | T__80 | T__81 | T__82 | T__83 | T__84 | T__85 | T__86 | T__87 | T__88 | T__89 | T__90 | T__91 | T__92 | T__93 | T__94 | T__95 | T__96 | T__97 | T__98 | T__99 | T__100 | T__101 | T__102 | T__103 | T__104 | T__105 | T__106 | T__107 | T__108 | T__109 | T__110 | T__111 | T__112 | T__113 | T__114 | T__115 | T__116 | T__117 | T__118 | T__119 | RULE_ID | RULE_NUMBER | RULE_STRING | RULE_ML_COMMENT | RULE_SL_COMMENT | RULE_WS | RULE_ANY_OTHER );";
        }
        public int specialStateTransition(int s, IntStream _input) throws NoViableAltException {
            IntStream input = _input;
        	int _s = s;
            switch ( s ) {
                    case 0 : 
                        int LA16_0 = input.LA(1);

                        s = -1;
                        if ( (LA16_0=='a') ) {s = 1;}

                        else if ( (LA16_0=='{') ) {s = 2;}

                        else if ( (LA16_0=='c') ) {s = 3;}

                        else if ( (LA16_0=='d') ) {s = 4;}

                        else if ( (LA16_0=='l') ) {s = 5;}

                        else if ( (LA16_0=='p') ) {s = 6;}

                        else if ( (LA16_0=='}') ) {s = 7;}

                        else if ( (LA16_0=='u') ) {s = 8;}

                        else if ( (LA16_0=='t') ) {s = 9;}

                        else if ( (LA16_0=='e') ) {s = 10;}

                        else if ( (LA16_0=='w') ) {s = 11;}

                        else if ( (LA16_0=='m') ) {s = 12;}

                        else if ( (LA16_0=='s') ) {s = 13;}

                        else if ( (LA16_0==',') ) {s = 14;}

                        else if ( (LA16_0=='f') ) {s = 15;}

                        else if ( (LA16_0=='o') ) {s = 16;}

                        else if ( (LA16_0=='r') ) {s = 17;}

                        else if ( (LA16_0=='i') ) {s = 18;}

                        else if ( (LA16_0=='-') ) {s = 19;}

                        else if ( (LA16_0=='k') ) {s = 20;}

                        else if ( (LA16_0=='g') ) {s = 21;}

                        else if ( (LA16_0=='h') ) {s = 22;}

                        else if ( (LA16_0=='v') ) {s = 23;}

                        else if ( (LA16_0=='.') ) {s = 24;}

                        else if ( (LA16_0=='b') ) {s = 25;}

                        else if ( (LA16_0=='n') ) {s = 26;}

                        else if ( (LA16_0=='F') ) {s = 27;}

                        else if ( (LA16_0=='S') ) {s = 28;}

                        else if ( (LA16_0=='R') ) {s = 29;}

                        else if ( (LA16_0=='D') ) {s = 30;}

                        else if ( (LA16_0=='E') ) {s = 31;}

                        else if ( (LA16_0=='L') ) {s = 32;}

                        else if ( (LA16_0=='O') ) {s = 33;}

                        else if ( (LA16_0=='N') ) {s = 34;}

                        else if ( (LA16_0=='I') ) {s = 35;}

                        else if ( (LA16_0=='^') ) {s = 36;}

                        else if ( ((LA16_0>='A' && LA16_0<='C')||(LA16_0>='G' && LA16_0<='H')||(LA16_0>='J' && LA16_0<='K')||LA16_0=='M'||(LA16_0>='P' && LA16_0<='Q')||(LA16_0>='T' && LA16_0<='Z')||LA16_0=='_'||LA16_0=='j'||LA16_0=='q'||(LA16_0>='x' && LA16_0<='z')) ) {s = 37;}

                        else if ( ((LA16_0>='0' && LA16_0<='9')) ) {s = 38;}

                        else if ( (LA16_0=='\"') ) {s = 39;}

                        else if ( (LA16_0=='/') ) {s = 40;}

                        else if ( ((LA16_0>='\t' && LA16_0<='\n')||LA16_0=='\r'||LA16_0==' ') ) {s = 41;}

                        else if ( ((LA16_0>='\u0000' && LA16_0<='\b')||(LA16_0>='\u000B' && LA16_0<='\f')||(LA16_0>='\u000E' && LA16_0<='\u001F')||LA16_0=='!'||(LA16_0>='#' && LA16_0<='+')||(LA16_0>=':' && LA16_0<='@')||(LA16_0>='[' && LA16_0<=']')||LA16_0=='`'||LA16_0=='|'||(LA16_0>='~' && LA16_0<='\uFFFF')) ) {s = 42;}

                        if ( s>=0 ) return s;
                        break;
                    case 1 : 
                        int LA16_39 = input.LA(1);

                        s = -1;
                        if ( ((LA16_39>='\u0000' && LA16_39<='\uFFFF')) ) {s = 120;}

                        else s = 42;

                        if ( s>=0 ) return s;
                        break;
            }
            NoViableAltException nvae =
                new NoViableAltException(getDescription(), 16, _s, input);
            error(nvae);
            throw nvae;
        }
    }
 

}